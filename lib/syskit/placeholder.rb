# frozen_string_literal: true

module Syskit
  # What the tasks of a placeholder model say (Syskit::Placeholder, the
  # task side of Models::Placeholder): they stand for a component providing
  # their model's services.
  module Placeholder
    def placeholder?
      true
    end

    def proxied_data_service_models
      model.proxied_data_service_models
    end
  end
end
