# frozen_string_literal: true

module Syskit
  module Robot
    # Which loaded task models can drive which device model, built once
    # when the app is loaded (so the load order of files does not matter).
    class DriverIndex
      # +task_models+: task models besides the loaded libraries' (those
      # made in Ruby by a test, see RobotDefinition).
      def initialize(orogen, app = nil, task_models: [])
        @orogen = orogen
        @app = app
        @drivers = Hash.new { |h, k| h[k] = [] }
        (orogen.each_task_model.to_a + task_models).each do |task_model|
          next if task_model.abstract?

          task_model.driver_services.each do |srv|
            srv.driven_device_model.fullfilled_models.each { |m| @drivers[m] |= [task_model] }
          end
        end
        # Sorted once here: every device asks for the drivers of its model.
        @drivers.each_value { |drivers| drivers.sort_by!(&:name).freeze }
      end

      NONE = [].freeze

      # The model a driver_for statement names: driver_for(CommonModels::Devices::GPS, ...)
      DRIVER_FOR = /driver_for\s*\(?\s*((?:::)?[A-Z]\w*(?:::[A-Z]\w*)*)/

      # Task models that can drive devices of +device_model+, by name.
      def drivers_for(device_model)
        @drivers.fetch(device_model, NONE)
      end

      # Sets the model and driver of +device+ and binds its slave devices,
      # or raises a DriverError (a DeclarationError for a slave).
      def resolve(device)
        device.assign_model(model_from_task(device)) unless device.model_resolved?
        # A driver service given with using: was bound when declared.
        unless device.driver_resolved? && device.using.equal?(device.driver_model.component_model)
          device.driver_model = device.using ? check_using(device) : single_driver(device)
        end
        device.resolve_slaves
      end

      private

      def model_from_task(device)
        task = device.requested_model
        models = task.declarable_device_models
        return models.first if models.size == 1

        if models.empty?
          raise DriverError.new(
            "#{task.name} drives no device",
            location: device.declared_at,
            hint: "declare driver_for DeviceModel, as: 'name' in the extension file of #{task.name}"
          )
        end

        raise DriverError.new("#{task.name} drives several devices: #{models.join(', ')}",
                              location: device.declared_at,
                              hint: "pass the device model and choose the driver with using: #{task.name}")
      end

      def check_using(device)
        using = device.using
        return using unless using.driver_services_for(device.model).empty?

        others = drivers_for(device.model).map(&:name)
        hint = if others.empty?
                 "declare driver_for #{device.model} in the extension file of #{using.name}"
               else
                 "drivers of #{device.model}: #{others.join(', ')}"
               end
        raise DeclarationError.new("#{using.name} does not drive #{device.model} (#{device})",
                                   location: device.declared_at, hint: hint)
      end

      def single_driver(device)
        drivers = drivers_for(device.model)
        return drivers.first if drivers.size == 1
        raise no_driver(device) if drivers.empty?

        example = "device(#{device.model}, as: '#{device.name}', using: OroGen.#{drivers.first.name.sub('::', '.')})"
        raise DriverError.new(
          "several drivers can drive #{device} (#{device.model}): #{drivers.map(&:name).join(', ')}",
          location: device.declared_at, hint: "choose one with the using: option, e.g. #{example}"
        )
      end

      def no_driver(device)
        libraries = libraries_mentioning(device.model)
        hint =
          if libraries.any?
            "add #{libraries.map { |l| "using_task_library '#{l}'" }.join(' or ')} " \
              "(its extension file declares a driver for #{short_name(device.model)})"
          else
            'load the task library of its driver with using_task_library, and declare ' \
              "driver_for #{device.model} in that library's extension file"
          end
        loaded = @orogen.loaded_library_names
        known = libraries.any? ? "task library #{libraries.join(' or ')} has one but is not loaded" : 'none is loaded'
        DriverError.new("no driver is known for #{device} (#{device.model}): #{known} " \
                        "(loaded task libraries: #{loaded.empty? ? 'none' : loaded.join(', ')})",
                        location: device.declared_at, hint: hint)
      end

      # Task libraries, not loaded yet, whose extension file has a
      # driver_for naming the model: what it writes must be the end of the
      # model's name (Devices::Bus::CAN for CommonModels::Devices::Bus::CAN,
      # not for an app's own MyApp::Devices::Bus::CAN).
      def libraries_mentioning(model)
        return [] unless @app && model.name

        segments = model.name.split('::')
        (@orogen.available_library_names - @orogen.loaded_library_names).select do |lib|
          @app.extension_files(lib, @orogen.spec_path(lib)).any? do |file|
            UserFile.read(file).scan(DRIVER_FOR).any? do |(written)|
              names = written.delete_prefix('::').split('::')
              names.last == segments.last && segments.last(names.size) == names
            end
          end
        end
      end

      def short_name(model)
        model.name.to_s.split('::').last
      end
    end
  end
end
