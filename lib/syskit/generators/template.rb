# frozen_string_literal: true

require 'erb'

module Syskit
  module Generators
    # An ERB template of templates/, rendered with plain local variables.
    #
    # Model files nest their body in the app's modules, at a depth that
    # depends on the name. Templates therefore write the body at column 0
    # between +<%= modules.open %>+ and +<%= modules.close %>+; rendering
    # indents it by the depth of the nesting, so templates stay readable.
    class Template
      DIR = File.expand_path('../../../templates', __dir__)
      BEGIN_BODY = "\0begin-body"
      END_BODY = "\0end-body"

      # Nested +module+ statements around a template's body.
      class Modules
        attr_reader :names

        def initialize(names)
          @names = names
        end

        # The opening lines, then the marker of the body's start.
        def open
          lines = names.each_with_index.map { |name, i| "#{'  ' * i}module #{name}" }
          (lines + [BEGIN_BODY]).join("\n")
        end

        # The marker of the body's end, then the closing lines.
        def close
          lines = names.each_index.map { |i| "#{'  ' * i}end" }.reverse
          ([END_BODY] + lines).join("\n")
        end
      end

      # Renders templates/NAME.erb with +locals+ as local variables.
      def self.render(name, **locals)
        path = File.join(DIR, "#{name}.erb")
        text = ERB.new(File.read(path), trim_mode: '-').result_with_hash(locals)
        indent_bodies(text, locals.values.grep(Modules).first)
      end

      # Indents the lines between the body markers, leaving blank lines empty.
      def self.indent_bodies(text, modules)
        return text unless modules

        depth = 0
        text.lines.each_with_object(+'') do |line, out|
          if line.chomp == BEGIN_BODY then depth = modules.names.size
          elsif line.chomp == END_BODY then depth = 0
          else out << (line.strip.empty? ? "\n" : "#{'  ' * depth}#{line}")
          end
        end
      end
    end
  end
end
