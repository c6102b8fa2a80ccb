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
      found = []
      each_node(parse(source, names)) do |node|
        name, arguments = SHAPES[node[0]]&.call(node)
        next unless name.is_a?(Array) && name[0] == :@ident && names.include?(name[1])

        first = arguments.is_a?(Array) && arguments[0] == :args_add_block ? arguments[1].first : nil
        found << Call.new(name[1], literal(first), name[2][0])
      end
      found.sort_by(&:line)
    end

    # The values given to the attribute +name+ in +source+
    # (+Roby.app.auto_load_models = false+), in source order: true, false,
    # or nil for a value that is not one of these literals.
    def assignments(source, name)
      name = name.to_s
      found = []
      each_node(parse(source, [name])) do |node|
        next unless assignment_of?(node, name)

        value = node[2]
        found << (value[1][1] == 'true' if value[0] == :var_ref && value[1][0] == :@kw)
      end
      found
    end

    # Ruby's syntax tree of +source+, nil when the source names none of
    # +names+: a call or an assignment has its name in the text, and a
    # source without any is not parsed (Ripper takes 0.4 s on a robot
    # configuration of 10,000 deployments, none of which registers an
    # app). Ripper is loaded here: most commands parse no source.
    def parse(source, names)
      return if names.none? { |name| source.include?(name) }

      require 'ripper'
      Ripper.sexp(source)
    end

    # Every node of +tree+, depth first in source order.
    def each_node(node, &block)
      return unless node.is_a?(Array)

      yield node
      node.each { |child| each_node(child, &block) }
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
