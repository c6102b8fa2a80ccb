# frozen_string_literal: true

require 'helper'

module Syskit
  # Roby's task services as Syskit's files meet them: a task model may
  # provide one (Syskit::LoggerService), and every data service, device
  # and bus model is one (Roby::TaskService.each_submodel lists them).
  class TestRobyTaskService < Minitest::Test
    TaskService = Compat::Roby::TaskService

    def test_the_logger_service_is_a_task_service
      assert_includes TaskService.each_submodel.to_a, Syskit::LoggerService
      assert_same TaskService, Syskit::LoggerService.supermodel
      assert_equal 'Syskit::LoggerService', Syskit::LoggerService.to_s
    end

    def test_service_device_and_bus_models_are_listed_as_task_services
      srv = DataService.new_submodel
      device = Device.new_submodel
      listed = TaskService.each_submodel.to_a
      [DataService, Device, ComBus, srv, device].each { |model| assert_includes listed, model }
    end

    def test_task_services_made_from_one_are_listed_under_it_and_the_root
      parent = TaskService.new_submodel(name: 'Parent')
      child = parent.new_submodel(name: 'Child')
      assert_equal [child], parent.each_submodel.to_a
      assert_includes TaskService.each_submodel.to_a, child
      refute_includes parent.each_submodel.to_a, DataService
    end
  end
end
