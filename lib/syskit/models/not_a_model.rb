# frozen_string_literal: true

module Syskit
  module Models
    # Why a value given where a model is expected (driver_for, provides)
    # is not one, for the hint of the error.
    module NotAModel
      module_function

      # What to check when +statement+ (driver_for, provides) is given
      # +value+, which is no model: nil is what a constant, a method or a
      # lookup gave (a model whose file was not required, a constant set
      # before its model existed); a name is not the model.
      def hint(statement, value, location)
        written = location&.source_line.to_s[/\b#{statement}[\s(]+([\w:.]+)/, 1]
        written = nil if written == 'nil'
        case value
        when nil
          "#{written || 'the model given'} is nil here: require the file that defines the model before this " \
          "line (e.g. require 'models/devices/gps'), and check that nothing sets it to nil"
        when String, Symbol
          "give the model itself, not its name: #{statement} #{value.to_s.sub(/\A::/, '')}"
        else 'give a model made by device_type, com_bus_type or data_service_type'
        end
      end
    end
  end
end
