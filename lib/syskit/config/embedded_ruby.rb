# frozen_string_literal: true

module Syskit
  module Config
    # Ruby embedded in a configuration file between <%= and %>, as Rock's
    # loader evaluates it before reading the YAML:
    #
    #   vocabulary: "<%= ENV['AUTOPROJ_CURRENT_ROOT'] %>/install/share/vocabulary.txt"
    #
    # Each expression is evaluated on its own, at the top level, and
    # replaced by its value as text (nothing for nil). Only <%= ... %> is
    # Ruby: other text, <% without = included, is left as it is.
    module EmbeddedRuby
      EXPRESSION = /<%=(.*?)%>/m
      # A binding of its own for each expression, at the top level: local
      # variables do not leak from one expression, or file, to the next.
      FRESH_BINDING = TOPLEVEL_BINDING.eval('-> { binding }')

      module_function

      # +text+ (the section of +path+ whose first line is +first_line+)
      # with its expressions replaced by their values.
      def expand(text, path, first_line)
        return text unless text.include?('<%=')

        text.gsub(EXPRESSION) do
          match = Regexp.last_match
          line = first_line + text[0, match.begin(0)].count("\n")
          evaluate(match[1].strip, path, line)
        end
      end

      def evaluate(code, path, line)
        UserCode.guard(path: path, error_class: ConfigurationError,
                       context: "in the Ruby of <%= #{code} %>") do
          FRESH_BINDING.call.eval(code, path, line).to_s
        end
      end
    end
  end
end
