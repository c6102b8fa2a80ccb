# frozen_string_literal: true

require 'syskit/models/not_a_model'

require 'syskit/models/bound_data_service'
require 'syskit/models/component_merging'
require 'syskit/models/port_mapper'
require 'syskit/models/service_lookups'
require 'syskit/models/driver_services'
require 'syskit/models/task_arguments'
require 'syskit/models/task_requirements'

module Syskit
  module Models
    # What task models and composition models have in common, as Syskit's
    # Component: the data services they provide (+provides Srv, as: 'name'+,
    # each then reachable as +name_srv+), their arguments, the requirement
    # statements (+with_conf+, +use+...), and what they fullfill.
    module Component
      include TaskArguments
      include TaskRequirementStatements
      include ServiceLookups
      include DriverServices
      include ComponentMerging

      class << self
        # Bumped whenever a component model gains a service or a stub: the
        # cached views below (which merge a model's declarations with its
        # parents') are then computed again.
        def declarations_version
          @declarations_version ||= 0
        end

        def declarations_changed
          @declarations_version = declarations_version + 1
        end
      end

      # A submodel made in Ruby, as Syskit's tests and model helpers make
      # them: +Syskit::Component.new_submodel(name: 'Cmp') { provides Srv,
      # as: 'srv' }+. The one implementation behind every component
      # model's new_submodel (task contexts, Ruby tasks, compositions): each
      # says how its submodel class is made (#submodel_class).
      def new_submodel(name: nil, &block)
        model = submodel_class
        model.instance_variable_set(:@given_name, name) if name
        model.class_eval(&block) if block
        model
      end

      # The model's constant name, else the one given to new_submodel.
      def name
        super || @given_name
      end

      # Documentation of the model (the comment above its declaration).
      attr_writer :doc

      def doc(text = nil)
        return @doc if text.nil?

        @doc = text.to_s
      end

      # Marks the model abstract: it stands for its submodels (and a
      # composition's specializations), and cannot be put in a network as
      # it is.
      def abstract
        @abstract = true
      end

      def abstract?
        @abstract == true
      end

      # A Queries::ComponentMatcher finding the tasks of this model.
      def match
        Queries::ComponentMatcher.new.with_model(self)
      end

      # Whether it is a submodel made by +specialize+ for the use of one
      # requirement or test (Syskit's private specializations).
      def private_specialization?
        @private_specialization == true
      end

      # Whether it is a placeholder model (see Placeholder): a component
      # model declared in a file is not.
      def placeholder?
        false
      end

      # Services by name, inherited ones included.
      # Those of the parent model are promoted to this one (their
      # +component_model+ is this model, as in Syskit), so that selecting
      # +Sub.gps_srv+ selects Sub.
      def services
        cached(:services) do
          inherited = superclass.respond_to?(:services) ? superclass.services : {}
          own = @services || {}
          promoted = {}
          inherited.each do |full_name, srv|
            promoted[full_name] = own[full_name] || promote(srv, own, promoted)
          end
          promoted.merge(own).freeze
        end
      end

      # Services whose model is or provides +service_model+, in declaration order.
      def services_fulfilling(service_model)
        cached(:fulfilling, service_model) { services.values.select { |srv| srv.fullfills?(service_model) }.freeze }
      end

      # The service of full name +name+ ('gps', or 'stereo.left' for a slave).
      def find_service(name)
        services[name.to_s]
      end
      alias find_data_service find_service

      # Enumerates the services, inherited ones included, in declaration order.
      def each_data_service(&)
        services.each_value(&)
      end

      # Declares that this component provides the data service +model+ under
      # the name +as+, with optional +'service_port' => 'component_port'+
      # mappings; +slave_of: 'name'+ makes it a slave of the service +name+
      # (its full name is then +name.as+).
      def provides(model, mappings = {}, as: nil, slave_of: nil, **more)
        location = Location.of_caller
        return (@task_services ||= []) << model if model.is_a?(Compat::Roby::TaskServiceModel) && as.nil?

        unless model.is_a?(DataServiceModel)
          raise DeclarationError.new("provides expects a data service model, got #{model.inspect}",
                                     location: location, hint: NotAModel.hint('provides', model, location))
        end
        unless as
          raise DeclarationError.new("provides #{model} needs a service name",
                                     location: location, hint: "write provides #{model}, as: 'name'")
        end

        add_service(as, model, mappings.merge(more), location, slave_of: slave_of)
      end

      # Whether this model is +model+ (or a submodel of it) or provides it;
      # given a list, whether it fullfills each of them. A placeholder is
      # fullfilled by what provides all it stands for, a specialization by
      # a model of its task model having its required dynamic services.
      def fullfills?(model)
        return model.all? { |m| fullfills?(m) } if model.is_a?(Array)
        return self <= model || fullfills_placeholder_or_specialization?(model) if model.is_a?(Class)

        model.is_a?(DataServiceModel) && !services_fulfilling(model).empty?
      end
      alias fulfills? fullfills?

      # Syskit's +provides?(Srv)+: whether a service of the model fullfills +Srv+.
      def provides?(service_model)
        !services_fulfilling(service_model).empty?
      end

      # The model, its parent models up to Syskit::AbstractComponent, and
      # every service model it provides (with what they provide).
      def fullfilled_models
        cached(:fullfilled_models) do
          chain = ancestors.take_while { |m| m != Syskit::AbstractComponent }.grep(Class)
          chain << Syskit::AbstractComponent
          services.each_value { |srv| srv.model.each_fullfilled_model { |m| chain << m unless chain.include?(m) } }
          chain.freeze
        end
      end

      def each_fullfilled_model(&block)
        return enum_for(__method__) unless block

        fullfilled_models.each(&block)
      end

      private

      def fullfills_placeholder_or_specialization?(model)
        return model.fullfilled_by?(self) if model.respond_to?(:placeholder?) && model.placeholder?
        return false unless model.respond_to?(:each_required_dynamic_service) && !model.concrete_model.equal?(model)

        concrete_model <= model.concrete_model &&
          model.each_required_dynamic_service.all? { |srv| find_data_service(srv.full_name)&.same_service?(srv) }
      end

      # The class of a new submodel (see #new_submodel).
      def submodel_class
        Class.new(self)
      end

      # A view computed once per +key+ (and +subkey+), until declarations change.
      def cached(key, subkey = nil)
        version = Component.declarations_version
        if @cache_version != version
          @cache = {}
          @cache_version = version
        end
        table = subkey.nil? ? @cache : (@cache[key] ||= {}.compare_by_identity)
        slot = subkey.nil? ? key : subkey
        table.fetch(slot) { table[slot] = yield }
      end

      def add_service(name, model, mappings, location, slave_of: nil)
        name = name.to_s
        check_service_options(name, mappings, location)
        master = master_service(slave_of, location) if slave_of
        full_name = master ? "#{master.full_name}.#{name}" : name
        existing = find_service(full_name)
        check_override(existing, model, location) if existing

        port_mappings = PortMapper.new(self, model, mappings, location).map
        register_service(BoundDataService.new(self, name, model, port_mappings, location, master: master))
      end

      # Makes +srv+ (a BoundDataService of this model) one of its services.
      def register_service(srv)
        (@services ||= {})[srv.full_name] = srv
        include_service_models(srv)
        Component.declarations_changed
        define_service_reader(srv)
        srv.master&.define_slave_reader(srv)
        srv
      end

      # Its tasks are of the service models it provides, as in Syskit, where
      # these are modules of the task model (+task.is_a?(Srv)+).
      def include_service_models(srv)
        srv.each_fullfilled_model.to_a.reverse_each { |m| include(m) if m.is_a?(DataServiceModel) }
      end

      # +name_srv+ on the model and its tasks, for a master service:
      # Syskit's way of selecting one service of a component
      # (+use('pose' => Task.gps_srv)+).
      # Submodels inherit the reader and get their own (promoted) service.
      def define_service_reader(srv)
        return unless srv.master?

        reader = "#{srv.name}_srv"
        name = srv.full_name
        define_singleton_method(reader) { find_service(name) } unless singleton_class.method_defined?(reader, false)
        define_method(reader) { find_data_service(name) } unless method_defined?(reader, false)
      end

      # A parent's service +srv+ as a service of this model, its master
      # being this model's (+own+ or already +promoted+).
      def promote(srv, own, promoted)
        master = srv.master && (own[srv.master.full_name] || promoted[srv.master.full_name])
        copy = srv.attach(self, master: master)
        master&.define_slave_reader(copy)
        copy
      end

      # A submodel may declare again a service of its parent model, with
      # the parent service's model or one providing it (a driver package's
      # subclass driving a more specific device); a service is declared
      # once per model.
      def check_override(existing, model, location)
        existing = existing.demoted
        if @services&.key?(existing.full_name)
          raise DeclarationError.new("#{name} already has a #{existing} declared at #{existing.declared_at}",
                                     location: location, hint: "give this one another name with as: 'other_name'")
        end
        return if model.fullfills?(existing.model)

        raise DeclarationError.new(
          "#{model} cannot replace the #{existing} declared at #{existing.declared_at}: " \
          "it does not provide #{existing.model}",
          location: location,
          hint: "give the service another name with as: 'other_name', or use a model providing #{existing.model}"
        )
      end

      def master_service(slave_of, location)
        name = slave_of.respond_to?(:full_name) ? slave_of.full_name : slave_of.to_s
        found = find_service(name)
        return found if found

        known = services.keys.sort
        hint = known.empty? ? "declare the master first: driver_for Model, as: 'name'" : "services: #{known.join(', ')}"
        raise DeclarationError.new(
          "slave_of: '#{name}' names no service of #{self.name}#{Naming.did_you_mean(name, known)}",
          location: location, hint: hint
        )
      end

      def check_service_options(name, mappings, location)
        # Syskit takes any name (common_models names services after their
        # models: as: 'Test'; its tests after anonymous ones, as: srv.to_s)
        # but a dot, which separates a slave's name from its master's.
        if name.empty? || name.include?('.')
          raise DeclarationError.new("'#{name}' is not a valid service name",
                                     location: location, hint: "use a name without dots, e.g. as: 'gps'")
        end
        options = mappings.keys.grep(Symbol)
        return if options.empty?

        raise DeclarationError.new(
          "unknown option #{options.map { |o| "#{o}:" }.join(', ')}",
          location: location,
          hint: "the only option is as: 'name'; port mappings are written 'service_port' => 'task_port'"
        )
      end
    end
  end
end
