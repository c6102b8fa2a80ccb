# frozen_string_literal: true

require 'syskit/models/not_a_model'

require 'syskit/models/component_merging'
require 'syskit/models/data_accessors'
require 'syskit/models/service_declarations'
require 'syskit/models/service_lookups'
require 'syskit/models/driver_services'
require 'syskit/models/task_arguments'
require 'syskit/models/task_requirements'

module Syskit
  module Models
    # What task models and composition models have in common, as Syskit's
    # Component: the data services they provide (see ServiceDeclarations),
    # their arguments, the requirement statements (+with_conf+, +use+...),
    # and what they fullfill.
    module Component
      include ServiceDeclarations
      include TaskArguments
      include TaskRequirementStatements
      include ServiceLookups
      include DriverServices
      include ComponentMerging
      include DataAccessors

      class << self
        # Bumped whenever a component model's declarations change (a
        # service, a stub, an argument, a child or connection of a
        # composition, a configuration hook): what models keep computed
        # from their declarations and their parents' (the views below,
        # default arguments, port mappings...) is then computed again.
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

      # A task of this model marked abstract (Syskit's +create_proxy_task+):
      # it stands in a plan for a task still to be chosen.
      def create_proxy_task
        task = new
        task.abstract = true
        task
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

      # The services required from dynamic services (see
      # DynamicServices#require_dynamic_service), inherited ones included,
      # in the order they were required: none for a model without dynamic
      # services.
      def required_dynamic_services
        inherited = superclass.respond_to?(:required_dynamic_services) ? superclass.required_dynamic_services : []
        inherited + (@required_dynamic_services || [])
      end

      # Enumerates them, as Syskit's model-level method: each a service of
      # this model (+srv.model+, +srv.dynamic_service_options+). Without a
      # block, the list (Syskit's tests ask it +empty?+).
      def each_required_dynamic_service(&)
        return required_dynamic_services unless block_given?

        required_dynamic_services.each(&)
      end

      # Whether this model is +model+ (or a submodel of it) or provides it;
      # given a list, whether it fullfills each of them. A placeholder is
      # fullfilled by what provides all it stands for, a specialization by
      # a model of its task model having its required dynamic services;
      # requirements, by one that fullfills each model they require.
      def fullfills?(model)
        return model.all? { |m| fullfills?(m) } if model.is_a?(Array)
        return fullfills?(model.models) if model.is_a?(InstanceRequirements)
        return self <= model || fullfills_placeholder_or_specialization?(model) if model.is_a?(Class)
        return self <= model if model.is_a?(Compat::Roby::TaskServiceModel)

        model.is_a?(DataServiceModel) && !services_fulfilling(model).empty?
      end
      alias fulfills? fullfills?

      # Syskit's +provides?(Srv)+: whether a service of the model fullfills +Srv+.
      def provides?(service_model)
        !services_fulfilling(service_model).empty?
      end

      # The model, its parent models up to Syskit::AbstractComponent, and
      # every service model it provides (with what they provide), as
      # Syskit's +fullfilled_model+: a private specialization (see
      # #specialize) is not among them, it stands for its concrete model.
      def fullfilled_model
        cached(:fullfilled_model) do
          chain = ancestors.take_while { |m| m != Syskit::AbstractComponent }.grep(Class)
          chain.reject! { |m| m.respond_to?(:private_specialization?) && m.private_specialization? }
          chain << Syskit::AbstractComponent
          chain.concat(ancestors.grep(Compat::Roby::TaskServiceModel))
          services.each_value { |srv| srv.model.each_fullfilled_model { |m| chain << m unless chain.include?(m) } }
          chain.freeze
        end
      end

      def each_fullfilled_model(&block)
        return enum_for(__method__) unless block

        fullfilled_model.each(&block)
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
    end
  end
end
