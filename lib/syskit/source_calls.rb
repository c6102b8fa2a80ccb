# frozen_string_literal: true

module Syskit
  # Calls of given methods in a Ruby source, found by Ruby's own parser
  # before the file runs (register_app in robot configurations, deployment
  # statements in .orogen files): comments and strings that mention a call
  # are not calls, and are never taken for one.
  module SourceCalls
    # A call found: the method's name, its first argument's text when it
    # is a plain string literal (nil when it is computed), and its line.
    Call = Struct.new(:name, :argument, :line)

    # A call node is [name node, arguments node] in one of these shapes:
    # name 'x' / recv.name 'x' / (recv.)name('x').
    SHAPES = {
      command: ->(node) { [node[1], node[2]] },
      command_call: ->(node) { [node[3], node[4]] },
      method_add_arg: lambda do |node|
        callee = node[1]
        name = callee[0] == :fcall ? callee[1] : callee[3]
        [name, node[2] && node[2][1]]
      end
    }.freeze

    module_function

    # The calls of the methods +names+ in +source+, in source order; none
    # when Ruby cannot parse it (its evaluation reports that).
    def find(source, names)
      names = names.map(&:to_s)
      # A call has its name in the text: a source without any is not
      # parsed (Ripper takes 0.4 s on a robot configuration of 10,000
      # deployments, none of which registers an app).
      return [] if names.none? { |name| source.include?(name) }

      # Loaded here: most sources have no such call, and most commands
      # parse none.
      require 'ripper'
      found = []
      walk(Ripper.sexp(source), names, found)
      found.sort_by(&:line)
    end

    def walk(node, names, found)
      return unless node.is_a?(Array)

      name, arguments = SHAPES[node[0]]&.call(node)
      if name.is_a?(Array) && name[0] == :@ident && names.include?(name[1])
        first = arguments.is_a?(Array) && arguments[0] == :args_add_block ? arguments[1].first : nil
        found << Call.new(name[1], literal(first), name[2][0])
      end
      node.each { |child| walk(child, names, found) }
    end

    # The values given to the attribute +name+ in +source+
    # (+Roby.app.auto_load_models = false+), in source order: true, false,
    # or nil for a value that is not one of these literals.
    def assignments(source, name)
      name = name.to_s
      return [] unless source.include?(name)

      require 'ripper'
      found = []
      walk_assignments(Ripper.sexp(source), name, found)
      found
    end

    def walk_assignments(node, name, found)
      return unless node.is_a?(Array)

      if assignment_of?(node, name)
        value = node[2]
        found << (value[1][1] == 'true' if value[0] == :var_ref && value[1][0] == :@kw)
      end
      node.each { |child| walk_assignments(child, name, found) }
    end

    # [:assign, [:field, receiver, '.', [:@ident, name, position]], value]
    def assignment_of?(node, name)
      target = node[0] == :assign && node[1]
      target.is_a?(Array) && target[0] == :field && target[3].is_a?(Array) && target[3][0..1] == [:@ident, name]
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
