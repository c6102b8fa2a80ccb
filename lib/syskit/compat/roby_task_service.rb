# frozen_string_literal: true

module Syskit
  module Compat
    module Roby
      # Roby's task service models: what a task model provides without
      # ports or a name (+provides Syskit::LoggerService+, recorded on the
      # model). Syskit's service, device and bus models are task services
      # too: +Roby::TaskService.each_submodel+ lists them.
      class TaskServiceModel < Module
        def initialize(name, supermodel = nil)
          super()
          @given_name = name
          @submodels = []
          @supermodel = supermodel
        end

        # The model this one was made from (nil for Roby::TaskService).
        attr_reader :supermodel

        # A task service model made from this one (Roby's +task_service 'Name'+).
        def new_submodel(name: nil)
          model = TaskServiceModel.new(name, self)
          register_submodel(model)
          model
        end

        # The task service models made from this one, directly or not;
        # under Roby::TaskService, also every data service, device and bus
        # model (their roots are task services in Syskit).
        def each_submodel(&block)
          return enum_for(__method__) unless block

          @submodels.each(&block)
          return unless supermodel.nil?

          [Syskit::DataService, Syskit::Device, Syskit::ComBus].each do |root|
            yield root
            root.each_submodel(&block)
          end
        end

        # The name given at creation (Roby's, e.g. Roby::TaskService), else
        # the constant's.
        def name
          return @given_name if @given_name

          constant_name = super
          constant_name unless constant_name&.start_with?('#<')
        end

        def to_s
          name || 'anonymous task service'
        end
        alias inspect to_s

        protected

        def register_submodel(model)
          @submodels << model
          supermodel&.register_submodel(model)
        end
      end

      # The root of Roby's task services.
      TaskService = TaskServiceModel.new('Roby::TaskService')
    end
  end
end
