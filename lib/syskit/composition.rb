# frozen_string_literal: true

require 'syskit/models/composition'

module Syskit
  # A composition: components put together for one purpose, their ports
  # connected (Syskit::Composition). Models are subclasses:
  #
  #   class ArmControl < Syskit::Composition
  #     add OroGen.arm.Controller, as: 'controller'
  #     add Devices::Arm, as: 'arm'
  #     controller_child.command_port.connect_to arm_child.command_port
  #   end
  #
  # In a network, a composition is not deployed: it groups its children
  # (tasks or other compositions, +controller_child+), whose connections
  # the generator makes. It is named after where it stands in the plan
  # (+arm_control+, +arm_control.controller+ for a composition child).
  class Composition < Component
    extend Models::Composition

    attr_accessor :name, :parent

    def initialize(arguments = NO_ARGUMENTS)
      @children = {}
      @child_selection = {}
      super
    end

    # What was selected for each child, by role: an InstanceSelection (its
    # +selected+ requirements are what the child task was made from).
    attr_reader :child_selection

    # The child task of role +role+ (a task or a composition).
    def child_task(role)
      @children.fetch(role.to_s) do
        raise ArgumentError, "#{self} has no child '#{role}' (its children: #{@children.keys.sort.join(', ')})"
      end
    end
    alias find_child child_task

    def add_child(role, task)
      @children[role]&.remove_parent_task(self)
      @children[role] = task
      task.add_parent_task(self)
      task
    end

    # Roby's +depends_on(task, role: 'name')+ as Syskit's tests write it:
    # +task+ becomes the child +role+.
    def depends_on(task, role:)
      add_child(role.to_s, task)
      task
    end

    # Puts +new_task+ in the roles +task+ has (Roby's replacement of a
    # child, see Test::Plan#replace).
    def replace_child(task, new_task)
      @children.select { |_, child| child.equal?(task) }.each_key { |role| add_child(role, new_task) }
    end

    # Whether a connection of the model links the task ports +source+ and
    # +sink+ (Syskit::Port of the tasks filling its children, in this
    # direction), the children's ports mapped onto what fills them.
    def connects?(source, sink)
      model.port_connections.any? do |connection|
        Composition.resolved_to?(resolve_child_port(connection.from), source) &&
          Composition.resolved_to?(resolve_child_port(connection.to), sink)
      end
    end

    # Whether +resolved+ (a task and port name, see #resolve_child_port) is +port+.
    def self.resolved_to?(resolved, port)
      resolved && resolved[0].equal?(port.component) && resolved[1] == port.name
    end

    # Removes +task+ from the children.
    def remove_dependency(task)
      @children.delete_if { |_, child| child.equal?(task) }
      task.remove_parent_task(self)
    end
    alias remove_child remove_dependency

    # The child task of role +role+, or nil.
    def find_child_from_role(role)
      @children[role.to_s]
    end

    # The child of role +role+ as +from_model+ (this composition's model
    # or one of its parents) requires it: the task's service selected for
    # it, seen as the one data service the child requires; the task when
    # the child requires a component model or several services. Nil when
    # +from_model+ has no such child or the task has none in that role.
    def find_required_composition_child_from_role(role, from_model = model)
      child = from_model.find_child(role)
      task = child && find_child_from_role(role)
      return unless task

      services = child.models.grep(Models::DataServiceModel)
      return task if services.size != 1 || !task.respond_to?(:find_data_service)

      service = selected_service(role, task, services.first)
      service ? service.as(services.first) : task
    end

    # As find_required_composition_child_from_role, raising ArgumentError
    # when there is no such child.
    def required_composition_child_from_role(role, from_model = model)
      find_required_composition_child_from_role(role, from_model) ||
        raise(ArgumentError, "#{self} has no child with role #{role}")
    end

    # The children as [task, { role: name }] pairs, in the model's order.
    def each_child(&block)
      return enum_for(__method__) unless block

      @children.each { |role, task| yield task, { role: role } }
    end

    # Children by role.
    def children_by_role
      @children
    end

    def children
      @children.values
    end

    def has_role?(role) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
      @children.key?(role.to_s)
    end

    def each_role(&)
      @children.each_key(&)
    end

    # The port +name+ of the composition: the port of the child it is
    # exported from, down to the task that has it.
    def find_port(name)
      resolved = resolve_export(name.to_s)
      resolved && resolved[0].find_port(resolved[1])
    end

    # What the task the exported port +name+ comes from declares of it.
    def find_orogen_port(name)
      resolved = resolve_export(name.to_s)
      resolved && resolved[0].find_orogen_port(resolved[1])
    end

    # The task and port name the exported port +name+ is in the network.
    def resolve_export(name)
      export = model.exports[name]
      export && resolve_child_port(export.port)
    end

    # The task and port name that +port+ (a port of one of the model's
    # children) is in the network: the child task's port it maps to,
    # followed through the exports of a child composition. Nil when the
    # child was left out (or the export's own child was). A port the
    # selected component does not map keeps its name, so that the
    # connection reports the missing port rather than vanish.
    def resolve_child_port(port)
      task = @children[port.child_name]
      return unless task

      selected = @child_selection[port.child_name]&.selected
      name = Composition.port_name_in(selected, task.model, port.owner, port.owner_port)
      name ||= port.owner_port
      return task.resolve_export(name) if task.is_a?(Composition) && task.model.exports.key?(name)

      [task, name]
    end

    # The name of the port of +model+ (the component selected with
    # +selection+) that the port +port_name+ of +owner+ (a model the child
    # requires) is: through the selected service when there is one.
    def self.port_name_in(selection, model, owner, port_name)
      service = selection&.service || device_service(selection, model)
      if service && owner.is_a?(Models::DataServiceModel) && service.fullfills?(owner)
        return service.task_port_for(owner, port_name)&.name
      end

      Models.mapped_port_name(model, owner, port_name)
    end

    # The service through which a device's driver drives it.
    def self.device_service(selection, model)
      device = selection&.device
      return unless device
      return device.service if device.master_device

      model.driver_services_for(device.model).first
    end

    def ports
      model.ports
    end

    def to_s
      "#{model.short_name}#{" '#{name}'" if name}"
    end

    def inspect
      "#<#{self}>"
    end

    private

    # The service of +task+ selected for the child +role+, else the one
    # service of +task+ that provides +required+.
    def selected_service(role, task, required)
      selected = @child_selection[role.to_s]&.selected&.service
      return task.find_data_service(selected.full_name) if selected

      candidates = task.each_data_service.select { |srv| srv.fullfills?(required) }
      candidates.first if candidates.size == 1
    end
  end
end
