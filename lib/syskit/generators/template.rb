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

      # Text of several lines a template may insert with <%= %>: comments
      # made by {Template.comment}, module nesting. Any other inserted value
      # must hold on one line (see Output).
      class Lines < String
        # ERB calls to_s on what it inserts; a String subclass would
        # otherwise come back as a plain String.
        def to_s
          self
        end
      end

      # What a template is rendered into. The values of <%= %> tags go
      # through #value: a line break in one of them (a name, a doc string
      # from a spec) would start a line of live Ruby in the generated file,
      # so only Lines may hold several lines.
      class Output
        def initialize
          @text = +''
        end

        # The template's own text.
        def <<(text)
          @text << text
          self
        end

        # The value of a <%= %> tag.
        def value(text)
          if !text.is_a?(Lines) && text.match?(/[\r\n]/)
            raise GeneratorError.new("a generated line would be cut by a line break in #{text[0, 60].inspect}",
                                     hint: 'names given to generators hold on one line')
          end

          @text << text
          self
        end

        def to_s
          @text
        end
      end

      # ERB whose output is an Output.
      class Compiled < ERB
        def set_eoutvar(compiler, eoutvar = '_erbout')
          super
          compiler.insert_cmd = "#{eoutvar}.value"
          compiler.pre_cmd = ["#{eoutvar} = ::Syskit::Generators::Template::Output.new"]
          compiler.post_cmd = ["#{eoutvar}.to_s"]
        end
      end

      # +text+ as Ruby comment lines ("# " before each line), whatever
      # line breaks it holds.
      def self.comment(text)
        Lines.new(text.to_s.split(/\r\n|\r|\n/).map { |line| "# #{line}".rstrip }.join("\n"))
      end

      # Nested +module+ statements around a template's body.
      class Modules
        attr_reader :names

        def initialize(names)
          @names = names
        end

        # The opening lines, then the marker of the body's start.
        def open
          lines = names.each_with_index.map { |name, i| "#{'  ' * i}module #{name}" }
          Lines.new((lines + [BEGIN_BODY]).join("\n"))
        end

        # The marker of the body's end, then the closing lines.
        def close
          lines = names.each_index.map { |i| "#{'  ' * i}end" }.reverse
          Lines.new(([END_BODY] + lines).join("\n"))
        end
      end

      # Renders templates/NAME.erb with +locals+ as local variables.
      def self.render(name, **locals)
        path = File.join(DIR, "#{name}.erb")
        text = Compiled.new(File.read(path), trim_mode: '-').result_with_hash(locals)
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
