# frozen_string_literal: true

module Syskit
  module Orogen
    # Statements shared by the DSL objects of .orogen files: unknown calls are
    # explained with the statements that exist (see UserCode).
    module StatementsDSL
      include Types::TypeNames

      def explain_missing(name)
        statements = self.class.public_instance_methods(false).map(&:to_s) - %w[dsl_context]
        ["unknown statement '#{name}' in #{dsl_context}#{Naming.did_you_mean(name, statements)}",
         "the statements known here are #{statements.sort.join(', ')}"]
      end
    end
  end
end
