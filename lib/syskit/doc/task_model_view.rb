# frozen_string_literal: true

module Syskit
  module Doc
    # What the page of a task model shows: its interface from the .orogen
    # file (ports, dynamic ports, properties, operations), the services its
    # extension file declares, its configuration sections
    # (config/orogen/<lib>::<Task>.yml), where it is deployed and which
    # devices it drives.
    class TaskModelView
      # A property and the task model that declares it (a parent's, for
      # inherited ones).
      Property = Struct.new(:property, :owner) do
        def default?
          !property.default.nil?
        end
      end
      # A deployed task of this model: its deployment, the task library
      # that declares it (nil for one a robot configuration makes) and the
      # robots whose configuration uses it.
      Deployed = Struct.new(:name, :deployment, :library, :robots)

      attr_reader :model, :catalog

      # (+robot+ and +dot+ are for the views of profiles.)
      def initialize(catalog, model, **_site)
        @catalog = catalog
        @model = model
      end

      def spec
        model.spec
      end

      def library
        spec.library
      end

      def parent
        model.superclass if model.superclass.respond_to?(:spec) && model.superclass.spec
      end

      def children
        catalog.entries(:task_model).map(&:object).select { |m| m.superclass.equal?(model) }
      end

      # Static ports, by name.
      def ports
        model.ports.values.sort_by(&:name)
      end

      def dynamic_ports
        model.dynamic_ports
      end

      # What a port's declaration says of its connections.
      def port_notes(port)
        notes = []
        notes << 'multiplexes' if port.multiplexes?
        notes << 'needs a reliable connection' if port.reliable?
        notes << "buffer of at least #{port.buffer_size}" if port.buffer_size
        notes
      end

      def properties
        owners = spec_chain.reverse
        owners.flat_map { |s| s.properties.values.map { |p| [p.name, Property.new(p, s)] } }.to_h.values
              .sort_by { |p| p.property.name }
      end

      def operations
        spec.all_operations.values.sort_by(&:name)
      end

      # Services by full name: driver_for and provides declarations.
      def services
        model.services.values
      end

      # The configuration file of the task model, nil when there is none.
      def conf_file
        catalog.app.conf_file(model)
      end

      # Deployed tasks of this model: in the deployments of the loaded task
      # libraries, and in the robot configurations loaded.
      def deployments
        found = {}
        catalog.entries(:task_library).each do |entry|
          entry.object.deployments.each_value do |deployment|
            add_deployed(found, deployment.task_activities, entry.object)
          end
        end
        catalog.app.robot_configs.sort.each do |robot, config|
          add_deployed(found, config.deployed_tasks).each { |d| d.robots << robot }
        end
        found.values.sort_by { |d| [d.deployment, d.name] }
      end

      # For each profile, the devices this task model drives.
      def drives
        catalog.entries(:profile).filter_map do |entry|
          devices = entry.object.robot.each_master_device.select do |d|
            d.driver_resolved? && d.driver_model.component_model.equal?(model)
          end
          ModelView::Use.new(entry.object, devices) unless devices.empty?
        end
      end

      private

      # The Deployed entries of those of +tasks+ that run this model.
      def add_deployed(found, tasks, library = nil)
        tasks.select { |t| t.model.equal?(model) }.map do |t|
          found[[t.name, t.deployment.name]] ||= Deployed.new(t.name, t.deployment.name, library, [])
        end
      end

      def spec_chain
        chain = []
        current = spec
        while current
          chain << current
          current = current.superclass
        end
        chain
      end
    end
  end
end
