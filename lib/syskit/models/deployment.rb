# frozen_string_literal: true

require 'syskit/deployments_namespace'

module Syskit
  # Models of the things a robot is made of; here, of deployments.
  module Models
    # An oroGen deployment spec without a file, as Syskit's tests make one
    # (+Syskit::Models.create_orogen_deployment_model('motor_controller')+).
    def self.create_orogen_deployment_model(name = nil)
      Orogen::DeploymentSpec.new(name, Location.of_caller)
    end

    # An oroGen task model made in Ruby, of no task model yet (see
    # Orogen::ModelView.define), as Syskit's tests make them; its task
    # model is made by +TaskContext.define_from_orogen+.
    def self.create_orogen_task_context_model(name = nil, project: nil, subclasses: nil)
      Orogen::ModelView.define(name, project: project, subclasses: subclasses)
    end

    # The metamodel of deployments (extended onto Syskit::Deployment): a
    # deployment model stands for one oroGen deployment, its +orogen_model+
    # (an Orogen::DeploymentSpec: the process's name and the task instances
    # it runs), as Syskit's tests make them:
    #
    #   Syskit::Deployment.new_submodel(name: 'd') { task 'camera', Camera }
    #   Syskit::Deployment.define_from_orogen(spec, register: true)  # Deployments::D
    #
    # The models made from the root are known by their oroGen model
    # (+Syskit::Deployment.model_for(spec)+) until they are cleared.
    module Deployment
      # The deployment spec this model stands for.
      attr_reader :orogen_model

      # The model this one was made from (nil for Syskit::Deployment).
      attr_reader :supermodel

      # A new deployment model, of the deployment +name+ (or of
      # +orogen_model+); the block declares its tasks, evaluated on the spec
      # (+task 'name', TaskModel+).
      def new_submodel(name: nil, orogen_model: nil, &block)
        orogen_model ||= Orogen::DeploymentSpec.new(name, Location.of_caller)
        orogen_model.instance_eval(&block) if block
        submodel = Class.new(self)
        submodel.instance_variable_set(:@orogen_model, orogen_model)
        submodel.instance_variable_set(:@supermodel, self)
        register_submodel(submodel)
        submodel
      end

      # The model of the deployment +orogen_model+; with +register:+, a
      # named one is also the constant Deployments::<CamelCaseName>.
      def define_from_orogen(orogen_model, register: false)
        model = new_submodel(orogen_model: orogen_model)
        return model unless register && orogen_model.name

        ::Deployments.const_set(Naming.camelize(orogen_model.name), model)
        model
      end

      # The name of the deployment.
      def deployment_name
        orogen_model&.name
      end

      # The model made for the spec +orogen_model+; nil when there is none.
      def model_for(orogen_model)
        deployment_root.models_by_spec[orogen_model]
      end

      def has_model_for?(orogen_model) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        !model_for(orogen_model).nil?
      end

      # Enumerates the models made from this one, directly or not.
      def each_submodel(&block)
        return enum_for(__method__) unless block

        submodels.each do |model|
          yield(model)
          model.each_submodel(&block)
        end
      end

      def has_submodel?(model) # rubocop:disable Naming/PredicatePrefix -- MetaRuby's name
        each_submodel.include?(model)
      end

      # Forgets the models made from this one.
      def clear_submodels
        submodels.each(&:clear_submodels)
        submodels.each { |model| deployment_root.models_by_spec.delete(model.orogen_model) }
        @submodels = []
      end

      protected

      def submodels
        @submodels ||= []
      end

      def models_by_spec
        @models_by_spec ||= {}.compare_by_identity
      end

      def register_submodel(submodel)
        submodels << submodel
        deployment_root.models_by_spec[submodel.orogen_model] = submodel
      end

      private

      def deployment_root
        supermodel ? supermodel.send(:deployment_root) : self
      end
    end
  end
end
