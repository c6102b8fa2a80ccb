# frozen_string_literal: true

require 'syskit/models/child_port'
require 'syskit/models/port_lookup'
require 'syskit/models/child_service_view'
require 'syskit/models/composition_child_binding'
require 'syskit/models/composition_child_overload'

module Syskit
  module Models
    # A child of a composition model (Syskit's CompositionChild), what
    # +add(Model, as: 'name')+ returns and +name_child+ gives back: its
    # role, what it requires (an InstanceRequirements), and its ports
    # (+pose_child.pose_samples_port+), which connect to other children's.
    #
    # The statements that refine requirements change the child in place and
    # return it, as in Syskit: +add(Srv, as: 'x').with_arguments(speed: 2)+.
    class CompositionChild
      include PortLookup
      include ChildConnections
      include ChildReference
      include Binding
      include Overload

      # +reached_through+: for a child of a child composition, reached as
      # +first_child.src_child+, the child it is reached through (nil for a
      # composition's own child).
      # The readers explain_missing explains, by suffix.
      EXPLAINED = { '_port' => 'port', '_srv' => 'service', '_child' => 'child' }.freeze

      attr_reader :composition_model, :child_name, :requirements, :declared_at, :reached_through

      def initialize(composition_model, child_name, requirements = InstanceRequirements.new([Syskit::Component]),
                     location = nil, optional: false, reached_through: nil, facets: [], parent_model: nil)
        @composition_model = composition_model
        @parent_model = parent_model
        @facets = facets.freeze
        @child_name = child_name
        @declared_at = location
        @optional = optional
        @reached_through = reached_through
        self.requirements = requirements
      end

      # The service models the child was required as before an overload
      # replaced them with models that fullfill them: the child still has
      # their ports (mapped onto the models that replaced them), as the
      # blocks of specializations and the parent's declarations see it.
      attr_reader :facets

      # The same child, as seen from the submodel +model+ of its composition.
      def promote(model)
        CompositionChild.new(model, child_name, requirements, declared_at, optional: optional?, facets: facets,
                                                                           parent_model: parent_model)
      end

      # The same child, reached from +owner+ (requirements on its
      # composition model: +Cmp.use(...).x_child+), which is then its
      # #composition_model, as Syskit's +attach+.
      def attach(owner)
        attached = clone(freeze: false)
        attached.instance_variable_set(:@composition_model, owner)
        # Its ports and children are its own, reached from +owner+ too.
        attached.instance_variable_set(:@ports, nil)
        attached.instance_variable_set(:@children, nil)
        attached
      end

      # The same role of the same composition model (or requirements), as
      # Syskit compares children.
      def ==(other)
        other.instance_of?(self.class) && other.composition_model == composition_model &&
          other.child_name == child_name
      end

      # As a selection (+use('x' => first_child)+), the child itself, with
      # no particular service (see ChildReference).
      def referenced_child
        self
      end

      def referenced_service; end

      # Replaces what the child requires, and the +x_port+ readers with it.
      def requirements=(requirements)
        # Held by the model from now on, as Syskit freezes what it is given.
        @requirements = requirements.freeze
        @overload_info = nil
        @ports = nil
        @children = nil
        define_port_readers
        define_child_readers
      end

      # The child +name+ of the composition this child requires, reached
      # through it (+first_child.src_child+: what +use+ may give another
      # child, so that both share one task); nil when there is none.
      def find_child(name)
        child = child_composition_model&.find_child(name)
        return unless child

        (@children ||= {})[child.child_name] ||=
          CompositionChild.new(child.composition_model, child.child_name, child.requirements, child.declared_at,
                               optional: child.optional?, reached_through: self)
      end

      # The names of the children of a child composition (empty otherwise).
      def child_names
        child_composition_model&.child_names || []
      end

      # The child's name from the composition it belongs to: +first.src+
      # for a child reached through the child +first+ (the form of +use+'s
      # keys).
      def path
        reached_through ? "#{reached_through.path}.#{child_name}" : child_name
      end

      # The composition's own child this one is reached through (itself for
      # a composition's own child).
      def outermost_child
        reached_through ? reached_through.outermost_child : self
      end

      def models
        requirements.models
      end

      # The child's model, as Syskit's: its component model, else the
      # placeholder model of what it requires (see Placeholder).
      def model
        Placeholder.for(models)
      end

      # What the child's requirements stand for (see InstanceRequirements#model).
      def base_model
        requirements.base_model
      end

      def fullfills?(model)
        requirements.fullfills?(model)
      end
      alias fulfills? fullfills?

      def each_fullfilled_model(&)
        requirements.each_fullfilled_model(&)
      end

      def each_required_model(&)
        models.each(&)
      end

      def arguments
        requirements.arguments
      end

      def optional?
        @optional
      end

      # Syskit's +require_dynamic_service+ on a child (in the block of a
      # composition's dynamic service): the child is overloaded with a
      # specialization of its task model that has the instance +as+ of the
      # dynamic service +dynamic_name+; returns that service.
      def require_dynamic_service(dynamic_name, as:, **options)
        overloaded = requirements.with_dynamic_service(dynamic_name, as: as, **options)
        composition_model.overload(child_name, overloaded.component_model)
        overloaded.component_model.find_service(as.to_s)
      end

      # Marks the child optional: left out of the network when nothing
      # selects a component for it.
      def optional
        @optional = true
        self
      end

      # As InstanceRequirements#with_arguments and the others, in place.
      %i[with_arguments with_conf prefer_deployed_tasks deployed_as deployed_as_unmanaged use
         prefer_specializations].each do |statement|
        define_method(statement) do |*args, **options|
          self.requirements = requirements.public_send(statement, *args, **options)
          self
        end
      end

      # The ports of the child, by name: those of its component model (its
      # exported ports for a composition), or of its service models. A
      # composition child given selections (+add(Cmp.use(...), as:)+) has
      # the ports of the specialization they select, as in Syskit.
      def ports
        @ports ||= begin
          found = {}
          port_models.each do |model|
            model.ports.each_value do |port|
              found[port.name] ||= ChildPort.new(self, port, model)
            end
            break if model.is_a?(Class)
          end
          facets.each do |facet|
            facet.ports.each_value { |port| found[port.name] ||= ChildPort.new(self, port, facet) }
          end
          found.freeze
        end
      end

      # The child seen through +service_model+, one of the models it
      # fullfills: its ports are the service's (+out_child.as(Srv).out_port+).
      def as(service_model)
        ServiceView.new(self, service_model)
      end

      # The child seen through the service +name+ of its component model
      # (+cmp_child.test_srv.test_port+).
      def find_data_service(name)
        srv = requirements.component_model&.find_service(name)
        ServiceView.new(self, srv.model, srv) if srv
      end

      # The services of the child that provide +service_model+, each a view
      # of the child through it (Syskit's bound services of a child, seen
      # as +service_model+; +as_real_model+ sees one as its own model): of
      # its component model, or of the placeholder standing for its
      # service models.
      def find_all_data_services_from_type(service_model)
        component = requirements.component_model || Placeholder.for(models)
        component = component.component_model if component.is_a?(BoundDataService)
        component.services_fulfilling(service_model).map { |srv| ServiceView.new(self, service_model, srv) }
      end

      # Why +name+ is not a method of the child, when it is a port's or a
      # service's reader (+x_port+, +x_srv+); nil otherwise (see
      # UserCode.explain).
      def explain_missing(name)
        kind = EXPLAINED.find { |suffix, _| name.end_with?(suffix) }&.last
        return unless kind

        wanted = name.delete_suffix("_#{kind}")
        names = { 'port' => -> { ports.keys.sort }, 'service' => -> { service_names }, 'child' => -> { child_names } }
                .fetch(kind).call
        plural = kind == 'child' ? 'children' : "#{kind}s"
        ["#{self} has no #{kind} '#{wanted}'#{Naming.did_you_mean(wanted, names)}",
         names.empty? ? "#{model} has no #{plural}" : "its #{plural}: #{names.join(', ')}"]
      end

      def to_s
        "#{reached_through || composition_model.short_name}.#{child_name}_child"
      end
      alias inspect to_s
      alias short_name to_s

      private

      # The models whose ports the child has: a composition model narrowed
      # to the specialization the child's own selections select.
      def port_models
        return models unless requirements.composition? && !requirements.selections.empty?

        narrowed = requirements.narrow_model
        models.map { |m| m.equal?(requirements.component_model) ? narrowed : m }
      end

      # The composition model the child requires (narrowed as its ports
      # are), nil when it requires none.
      def child_composition_model
        return unless requirements.composition?

        requirements.selections.empty? ? requirements.component_model : requirements.narrow_model
      end

      # +x_child+ for each child of a child composition.
      # (the readers of that composition model, see
      # Composition#child_readers: a child it gets later is readable too).
      def define_child_readers
        model = child_composition_model
        extend(model.child_readers) if model.respond_to?(:child_readers)
      end

      def service_names
        model = requirements.component_model
        model ? model.each_data_service.select(&:master?).map(&:name).sort : []
      end

      # +x_port+ for each port and +x_srv+ for each service of the
      # component model, as singleton methods (no method_missing).
      def define_port_readers
        ports.each_key do |name|
          reader = "#{name}_port"
          define_singleton_method(reader) { ports.fetch(name) } unless respond_to?(reader)
        end
        requirements.component_model&.each_data_service do |srv|
          reader = "#{srv.name}_srv"
          next if !srv.master? || respond_to?(reader)

          define_singleton_method(reader) { find_data_service(srv.name) }
        end
      end
    end
  end
end
