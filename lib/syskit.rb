# frozen_string_literal: true

require 'syskit/version'
require 'syskit/iseq_cache'
require 'syskit/errors'
require 'syskit/model_errors'
require 'syskit/port_connection_check'
require 'syskit/naming'
require 'syskit/can'
require 'syskit/user_file'
require 'syskit/user_code'
require 'syskit/arguments'
require 'syskit/namespace'
require 'syskit/orogen_namespace'
require 'syskit/orogen/deployment_namespace'
require 'syskit/port'
require 'syskit/orogen/port'
require 'syskit/models/port'
require 'syskit/connection_resolution'
require 'syskit/types/type_names'
require 'syskit/types/registry'
require 'syskit/types/typekit_loader'
require 'syskit/models/model_registry'
require 'syskit/models/data_service_model'
require 'syskit/models/device_model'
require 'syskit/models/com_bus_model'
require 'syskit/models/task_context'
require 'syskit/abstract_component'
require 'syskit/orocos_task'
require 'syskit/bound_data_service'
require 'syskit/task_context'
require 'syskit/dependency_injection'
require 'syskit/instance_requirements'
require 'syskit/instance_selection'
require 'syskit/composition'
require 'syskit/models/placeholder'
require 'syskit/device_lookups'
require 'syskit/orogen/property'
require 'syskit/orogen/task_spec'
require 'syskit/orogen/deployment_spec'
require 'syskit/deployment'
require 'syskit/orogen/model_view'
require 'syskit/orogen/loader'
require 'syskit/ruby_task_context'
require 'syskit/queries/accessors'
require 'syskit/queries/plan_results'
require 'syskit/queries/component_matcher'
require 'syskit/queries/data_service_matcher'
require 'syskit/queries/port_matcher'
require 'syskit/robot/master_device_instance'
require 'syskit/robot/com_bus'
require 'syskit/robot/master_device'
require 'syskit/robot/slave_device_instance'
require 'syskit/robot/definition'
require 'syskit/robot/doc_comment'
require 'syskit/robot/dsl'
require 'syskit/robot/robot_definition'
require 'syskit/robot/driver_index'
require 'syskit/actions/profile'
require 'syskit/models/deployment_group'
require 'syskit/config/process_servers'
require 'syskit/config/robot_config'
require 'syskit/config/robot_dsl'
require 'syskit/config/global_conf'
require 'syskit/config/conf_file'
require 'syskit/config/section_values'
require 'syskit/network/generator'
require 'syskit/network/profile_plan'
require 'syskit/app'
require 'syskit/compat'
require 'syskit/dsl'

# Syskit's model layer: devices, buses, drivers and the networks that run
# them, without Roby or an Orocos runtime.
module Syskit
  # The root of all data service models.
  DataService = Models::DataServiceModel.new(location: Location.new(__FILE__, __LINE__))
  # The root of all device models: +Device.provides Syskit::Device+.
  Device = Models::DeviceModel.new(location: Location.new(__FILE__, __LINE__))
  Device.provides(DataService)
  # The root of all communication bus models.
  ComBus = Models::ComBusModel.new(location: Location.new(__FILE__, __LINE__))
  ComBus.provides(Device)

  class << self
    # The app DSL statements act on (see App#activate).
    attr_accessor :app

    # Adds Syskit declarations (driver_for, provides, configure, stub) to a
    # task model: +Syskit.extend_model OroGen.gps_ublox.Task do ... end+.
    def extend_model(model, &block)
      unless model.is_a?(Class) && model < TaskContext
        raise DeclarationError.new("extend_model expects a task model such as OroGen.canbus.Task, got #{model.inspect}",
                                   location: Location.of_caller,
                                   hint: 'extend the driver task model (OroGen.library.Task); device and service ' \
                                         'models are extended in their own device_type/data_service_type block')
      end

      model.class_eval(&block) if block
      model
    end

    # The robot configuration being loaded (config/robots/NAME.rb).
    # Elsewhere, what model files may ask of it (Config::GlobalConf).
    def conf
      app&.loading_robot_config || Config::GlobalConf.new
    end
  end
end

Module.include(Syskit::DSL::ModuleStatements)
TOPLEVEL_BINDING.receiver.extend(Syskit::DSL::TopLevelStatements)
