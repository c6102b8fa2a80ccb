# frozen_string_literal: true

module Syskit
  module Models
    # Syskit's +fullfills?+ for what knows the models it fullfills
    # (+fullfilled_models+): data service, device and bus models, and
    # requirements.
    module Fullfillment
      # Whether +model+ is one of the fullfilled models; given a list,
      # whether each of them is.
      def fullfills?(model)
        return model.all? { |m| fullfills?(m) } if model.is_a?(Array)

        fullfilled_models.include?(model)
      end
      alias fulfills? fullfills?
    end
  end
end
