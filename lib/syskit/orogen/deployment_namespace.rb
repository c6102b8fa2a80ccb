# frozen_string_literal: true

module Syskit
  module OroGenNamespace
    # Deployment models by name, as Syskit's +OroGen.deployments+ gives
    # them: +namespace.camera_process+ once the model of the deployment
    # 'camera_process' is registered; also +::Deployments::CameraProcess+
    # while OroGen's constant registration is on (see OroGenNamespace).
    class DeploymentNamespace
      def initialize
        @deployments = {}
        @registered_constants = []
      end

      # Makes +model+ (a Syskit::Deployment model) a reader of this
      # namespace, named after its deployment.
      def register_syskit_model(model)
        name = (model.deployment_name || model.name).to_s
        @deployments[name] = model
        define_singleton_method(name) { model }
        register_constant(name, model) if constant_registration?
        nil
      end

      # The registered deployment models, by name.
      def each(&)
        @deployments.each_value(&)
      end

      # Forgets every registered model, and the constants made for them.
      def clear
        @deployments.each_key { |name| singleton_class.send(:remove_method, name) }
        @deployments = {}
        @registered_constants.each do |name|
          ::Deployments.send(:remove_const, name) if ::Deployments.const_defined?(name, false)
        end
        @registered_constants = []
      end

      # What an unknown name's NoMethodError shows: the names it has.
      def inspect
        "#<deployments: #{@deployments.keys.sort.join(', ')}>"
      end
      alias to_s inspect

      private

      def constant_registration?
        defined?(::OroGen) && ::OroGen.respond_to?(:syskit_model_constant_registration?) &&
          ::OroGen.syskit_model_constant_registration?
      end

      def register_constant(name, model)
        constant = Naming.camelize(name)
        ::Deployments.const_set(constant, model)
        @registered_constants << constant
      end
    end
  end
end
