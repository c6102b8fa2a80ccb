# frozen_string_literal: true

module Syskit
  module Models
    # Syskit's +specialize+ on task models: a submodel made for one use
    # (a device, a definition, a test), to which +require_dynamic_service+
    # adds services without changing the task model itself.
    #
    #   rear = OroGen.stereo.Task.specialize
    #   rear.require_dynamic_service('export', as: 'rear')
    #   device(Devices::Camera, as: 'rear_cam', using: rear)
    #
    # Deployments of the task model run its specializations (see
    # #concrete_model). Part of TaskModel.
    module TaskSpecialization
      # A specialization of this model, named +name+ or after this model
      # (+stereo::Task{1}+).
      def specialize(name = nil)
        @specialization_count = (@specialization_count || 0) + 1
        # A submodel made in Ruby (see TaskContext.new_submodel), whose
        # ports require_dynamic_service can add to.
        model = new_submodel(name: name || "#{self.name}{#{@specialization_count}}")
        model.instance_variable_set(:@concrete_model, concrete_model)
        model.instance_variable_set(:@private_specialization, true)
        model
      end

      # Whether this model was made by #specialize.
      def specialization?
        !@concrete_model.nil?
      end

      # This model if it is a specialization, else a new one (Syskit's
      # name: helpers that require dynamic services call it first).
      def ensure_model_is_specialized
        specialization? ? self : specialize
      end

      # The model deployments run: this one, or the one a specialization
      # was made from (as Syskit's concrete_model).
      def concrete_model
        @concrete_model || self
      end
    end
  end
end
