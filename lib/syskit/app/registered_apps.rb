# frozen_string_literal: true

require 'ripper'

module Syskit
  class App
    # The +Roby.app.register_app 'path'+ calls of a robot configuration,
    # found by Ruby's own parser before the file runs (it runs after the
    # models the bundles it names make loadable): a comment or a string
    # that mentions register_app is not a call, and is never taken for one.
    class RegisteredApps
      # A call is [name node, arguments node] in one of these shapes:
      # register_app 'x' / recv.register_app 'x' / (recv.)register_app('x').
      CALLS = {
        command: ->(node) { [node[1], node[2]] },
        command_call: ->(node) { [node[3], node[4]] },
        method_add_arg: lambda do |node|
          callee = node[1]
          name = callee[0] == :fcall ? callee[1] : callee[3]
          [name, node[2] && node[2][1]]
        end
      }.freeze

      # [path, Location] of each call whose path is written as a string,
      # and the warnings for calls whose path is computed.
      def self.of(path)
        new(path).calls
      end

      def initialize(path)
        @path = path
        @found = []
        @warnings = []
      end

      def calls
        tree = Ripper.sexp(UserFile.read(@path))
        # A file Ruby cannot parse is reported when it is evaluated.
        walk(tree) if tree
        [@found, @warnings]
      end

      private

      def walk(node)
        return unless node.is_a?(Array)

        shape = CALLS[node[0]]
        name, arguments = shape&.call(node)
        return register(name, arguments) if name.is_a?(Array) && name[0] == :@ident && name[1] == 'register_app'

        node.each { |child| walk(child) }
      end

      def register(name, arguments)
        location = Location.new(@path, name[2][0])
        first = arguments.is_a?(Array) && arguments[0] == :args_add_block ? arguments[1].first : nil
        text = literal(first)
        return @found << [text, location] if text

        @warnings << Warning.new(
          'Roby.app.register_app with a path computed in Ruby: syskit reads bundles before robot ' \
          'configurations run, so this bundle is not searched',
          location: location,
          hint: "write the path as a string relative to the app (register_app '../other_bundle'), or name the " \
                'bundle in config/syskit.yml: bundles: [other_bundle]'
        )
      end

      # The text of a plain string literal ('x', "x", %q(x)): no
      # interpolation, no escape.
      def literal(node)
        return unless node.is_a?(Array) && node[0] == :string_literal

        parts = node[1].drop(1)
        return '' if parts.empty?
        return unless parts.size == 1 && parts[0][0] == :@tstring_content && !parts[0][1].include?('\\')

        parts[0][1]
      end
    end
  end
end
