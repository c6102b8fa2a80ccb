# frozen_string_literal: true

require 'syskit/generators/base'

module Syskit
  module Generators
    # `syskit gen bus can` (or bus/can): a communication bus model in
    # models/devices/bus/ (AppName::Devices::Bus::CAN) and its test.
    class BusGenerator < Base
      attr_reader :name

      # +name+: path or constant form; +options+: force:, dry_run:.
      def initialize(root, name, **options)
        super(root, **options)
        # Bus models live in Devices::Bus by convention; the seed writes the
        # namespace in the name (bus/name), accept it both ways.
        @name = Name.parse(name, what: 'bus', acronyms: acronyms).under('Bus')
      end

      # Relative path => content of the files to write.
      def files
        locals = {
          name: name, modules: modules_for('Devices', name), full_name: "#{app_name}::Devices::#{name}",
          service_name: name.path_segments.last
        }
        {
          name.model_path('devices') => Template.render('bus', **locals),
          name.test_path('devices') => Template.render('bus_test', **locals)
        }
      end
    end
  end
end
