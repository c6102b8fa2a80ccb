# frozen_string_literal: true

require 'syskit/generators/base'

module Syskit
  module Generators
    # `syskit gen dev type/manufacturer/model`: a device model in
    # models/devices/ (AppName::Devices::Type::Manufacturer::Model) and its test.
    class DeviceGenerator < Base
      attr_reader :name

      # +name+: path or constant form; +options+: force:, dry_run:.
      def initialize(root, name, **options)
        super(root, **options)
        @name = Name.parse(name, what: 'device', acronyms: acronyms)
      end

      # Relative path => content of the files to write.
      def files
        locals = {
          app_name: app_name, name: name, modules: modules_for('Devices', name),
          full_name: "#{app_name}::Devices::#{name}", require_path: "models/devices/#{name.path}",
          library: library_example, service_name: name.path_segments.last
        }
        {
          name.model_path('devices') => Template.render('device', **locals),
          name.test_path('devices') => Template.render('device_test', **locals)
        }
      end

      private

      # Rock names driver packages type_manufacturer (gps_ublox): the
      # likely task library of the driver, for the comments' examples.
      def library_example
        segments = name.path_segments
        segments.size > 1 ? segments[0..-2].join('_') : segments.first
      end
    end
  end
end
