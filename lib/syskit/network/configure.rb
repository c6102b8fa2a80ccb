# frozen_string_literal: true

module Syskit
  module Network
    # Step 5: configures tasks in order: configuration file sections first,
    # then the update_properties methods (where the model uses them, see
    # Models::TaskContext#use_update_properties?), then the configure
    # methods (which call super first), then the stub blocks, which stand
    # for the ports the real component creates.
    class Configure
      def initialize(context)
        @context = context
      end

      def run
        @context.order.each do |step|
          configure(step.task) if step.step == 'configure'
        end
      end

      # Configures one task: its sections, configure method and stubs.
      # Errors go to the context. A task made for no device (a component a
      # test configures on its own) has no device.
      def configure(task)
        device = task.requirements&.device
        apply_sections(task, device)
        user_code(task, device, 'update_properties') { task.update_properties } if task.model.use_update_properties?
        user_code(task, device, 'configure') { task.configure }
        component = task.orocos_task
        task.model.stub_blocks.each do |block|
          user_code(task, device, 'stub') { component.instance_exec(&block) }
        end
        user_code(task, device, 'stub') { component.run_stubbed_operations }
        create_expected_ports(task)
      rescue Syskit::Error => e
        @context.error(e)
      end

      private

      def apply_sections(task, device)
        location = sections_location(task, device)
        file = stubbed_sections(@context.app.conf_file(task.model), task.conf, location)
        unless file
          return if task.conf == ['default']

          raise ConfigurationError.new(
            "#{device || task} asks for sections #{task.conf.join(', ')} but #{task.model.name} " \
            'has no configuration file',
            location: location,
            hint: "create config/orogen/#{task.model.name}.yml with a '--- name:#{task.conf.last}' section"
          )
        end

        file.merged(task.conf, location: location).each do |key, value|
          apply_value(task, file, key, value)
        end
      end

      STUBBED_AT = Location.new('(stubbed sections)', 0)
      private_constant :STUBBED_AT

      # With stub deployments (the network of a test), the sections a task
      # asks for that its file lacks are empty, as Syskit's stubs make
      # them: a test of a composition needs no configuration file for each
      # of its children.
      def stubbed_sections(file, names, location)
        return file unless @context.stub_deployments

        missing = names - (file&.section_names || [])
        return file if missing.empty?

        (file || Config::ConfFile.empty('(stubbed)')).with_sections(missing, {}, location || STUBBED_AT)
      end

      # Where the task's sections were chosen: the device's with_conf, else
      # the requirement's (a composition's +conf+ or a child's with_conf),
      # else the definition the task was made for.
      def sections_location(task, device)
        return device.conf_location || device.declared_at if device

        requirement = task.requirements
        requirement&.conf_location || requirement&.declared_at || task.root_location
      end

      # Locations of keys are only looked up for errors.
      def apply_value(task, file, key, value)
        Config::SectionValues.apply(task.properties, file, task.conf, key, value)
      end

      def user_code(task, device, what, &)
        UserCode.guard(root: @context.app.root, error_class: ConfigureMethodError, &)
      rescue ConfigureMethodError => e
        # Said only for an error: a plan runs user code for every task.
        raise e.in_context("in #{task.model.name}'s #{what}#{" for #{device}" if device}")
      end

      # Per-device ports the bus driver must have: created by its stub blocks
      # when it has some (checked here), else by the component (created here).
      def create_expected_ports(task)
        expected = @context.expected_ports.fetch(task, nil)
        return unless expected

        stubs = task.model.stub_blocks
        expected.each do |port|
          next task.create_port(port.direction, port.name, port.type) if stubs.empty?
          next if task.created_ports.key?(port.name)

          raise missing_port(task, port, stubs.first)
        end
      end

      def missing_port(task, port, stub)
        file, line = stub.source_location
        created = task.created_ports.keys.sort.join(', ')
        NetworkError.new(
          "#{task.model.name}'s configure and stub did not create the #{port.direction} port '#{port.name}' " \
          "that #{port.device} needs (created: #{created.empty? ? 'none' : created})",
          location: Location.new(file, line),
          hint: 'the stub must create a port per attached device, from the property the configure method sets'
        )
      end
    end
  end
end
