# frozen_string_literal: true

module Syskit
  module Models
    # How task models stand for oroGen models: +define_from_orogen+ makes
    # the task model of an oroGen model (Orogen::ModelView, as
    # +Models.create_orogen_task_context_model+ makes one in Ruby), and
    # registers it on the OroGen namespace (+OroGen.lib.Task+); the lookups
    # find the task model of an oroGen model or name among the submodels.
    module TaskContextOrogen
      # The task model of +orogen_model+, made as a submodel of the task
      # model of its oroGen superclass (made too if there is none yet), or
      # of this model for an oroGen model with no superclass. With
      # +register:+, it is reachable by its oroGen name (see #register_model).
      def define_from_orogen(orogen_model, register: false)
        existing = find_model_by_orogen(orogen_model)
        return existing if existing

        parent = orogen_model.superclass
        supermodel = parent ? find_model_by_orogen(parent) || define_from_orogen(parent, register: register) : self
        model = supermodel.new_submodel(orogen_model: orogen_model)
        model.register_model if register && orogen_model.name
        model
      end

      # Makes the model reachable by its oroGen name on +OroGen+
      # (+OroGen.lib.Task+, and a constant when OroGen's constant
      # registration is on); the model is then named after that call chain.
      # Submodels may register elsewhere by overloading it.
      def register_model
        @registered_name = ::OroGen.register_syskit_model(self)
        @registered_on = ::OroGen
      end

      # The name #register_model gave it, nil when it was not registered.
      attr_reader :registered_name

      # Forgets the submodels, and their registrations on OroGen (those of
      # their own submodels as they clear theirs).
      def clear_submodels
        subclasses.each(&:deregister_model)
        super
      end

      # Undoes #register_model.
      def deregister_model
        @registered_on&.deregister_syskit_model(self)
        @registered_on = nil
        @registered_name = nil
      end

      # The task model, among this model's submodels, standing for the oroGen
      # model +orogen_model+ (a model's +orogen_model+, or its spec); nil
      # when there is none. Forgotten submodels (#clear_submodels) are gone.
      def find_model_by_orogen(orogen_model)
        each_submodel.find do |model|
          model.spec && (model.spec.equal?(orogen_model) || model.orogen_model == orogen_model)
        end
      end

      def has_model_for?(orogen_model) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
        !find_model_by_orogen(orogen_model).nil?
      end

      # As #find_model_by_orogen, raising UnknownName (an ArgumentError)
      # when no model stands for +orogen_model+.
      def model_for(orogen_model)
        find_model_by_orogen(orogen_model) ||
          raise(UnknownName.new("no task model of #{self} stands for the oroGen model #{orogen_model}",
                                location: Location.of_caller,
                                hint: 'define one with new_submodel, or load the .orogen file that declares it'))
      end

      # The submodel whose oroGen model is called +name+ ('lib::Task'), nil
      # when there is none.
      def find_model_from_orogen_name(name)
        each_submodel.find { |model| model.spec && model.spec.name == name }
      end
    end
  end
end
