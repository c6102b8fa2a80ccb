# frozen_string_literal: true

require 'helper'

module Syskit
  # Placeholder models as Syskit makes them (Models::Placeholder and its
  # Creation): what they derive from and fullfill, their cache, kinds of
  # placeholders of their own, merging them, and merging task models.
  class TestPlaceholders < Minitest::Test
    FILES = SelfTest::SERVICE_FILES

    Placeholder = Models::Placeholder

    def setup
      super
      load_app(my_app(nil, FILES), everything: true)
      @task_m = TaskContext.new_submodel(name: 'T') do
        output_port 'out', '/int32_t'
        input_port 'in', '/double'
      end
    end

    def test_a_placeholder_of_services_alone
      model = Placeholder.create_for([MyApp::Pose])
      assert_kind_of Placeholder, model
      assert model.abstract?
      assert_same model, model.concrete_model
      assert_same Syskit::Component, model.supermodel
      assert_equal [MyApp::Pose, DataService, AbstractComponent], model.each_fullfilled_model.to_a
      assert_equal MyApp::Pose, model.m0_srv.model
      assert_equal 'Syskit::Models::Placeholder<MyApp::Pose>', model.name
      assert model.new.placeholder?
      refute @task_m.new.placeholder?
    end

    def test_a_placeholder_on_a_task_model
      model = Placeholder.create_for([@task_m, MyApp::Pose, MyApp::Cmd], as: 'Both')
      assert_equal 'Both', model.name
      assert model < @task_m
      assert_same @task_m, model.supermodel
      assert_equal [MyApp::Pose, MyApp::Cmd], model.proxied_data_service_models
      assert_equal %w[cmd in out pose state], model.ports.keys.sort
      assert_equal(%w[m0 m1], %w[m0 m1].map { |name| model.find_service(name)&.name })
    end

    def test_the_arguments_of_for
      @task_m.provides MyApp::Cmd, as: 'cmd'
      assert_equal [@task_m, [MyApp::Pose], nil], Placeholder.resolve_models_argument([MyApp::Pose, @task_m])
      assert_equal [Syskit::Component, [MyApp::Pose], nil], Placeholder.resolve_models_argument([MyApp::Pose])
      assert_equal [@task_m, [], @task_m.cmd_srv],
                   Placeholder.resolve_models_argument([MyApp::Cmd], component_model: @task_m.cmd_srv)
      assert_raises(ArgumentError) { Placeholder.resolve_models_argument([@task_m, @task_m.cmd_srv]) }
    end

    def test_for_caches_until_the_component_model_clears_its_submodels
      model = Placeholder.for([@task_m, MyApp::Pose])
      assert_same model, Placeholder.for(Set[MyApp::Pose], component_model: @task_m)
      @task_m.clear_submodels
      refute_same model, Placeholder.for([@task_m, MyApp::Pose])
      assert_same @task_m, Placeholder.for([@task_m])
    end

    def test_for_a_service_gives_the_service_of_the_placeholder
      @task_m.provides MyApp::Cmd, as: 'cmd'
      assert_equal @task_m.cmd_srv, Placeholder.for([@task_m.cmd_srv])
      srv = Placeholder.for([MyApp::Pose], component_model: @task_m.cmd_srv)
      assert_equal 'cmd', srv.name
      assert_equal [MyApp::Pose], srv.component_model.proxied_data_service_models
    end

    def test_specialized_placeholders
      extension = Module.new do
        def special_task?
          true
        end
      end
      kind = Placeholder.new_specialized_placeholder(task_extension: extension) do
        define_method(:special?) { true }
      end
      model = kind.for([MyApp::Pose], component_model: @task_m)
      assert_kind_of kind, model
      assert_kind_of Placeholder, model
      assert model.special?
      assert model.new.special_task?
      refute_same model, Placeholder.for([MyApp::Pose], component_model: @task_m)
    end

    def test_merging_placeholders
      sub_m = @task_m.new_submodel
      pose = Placeholder.for([MyApp::Pose], component_model: @task_m)
      odometry = Placeholder.for([MyApp::Odometry], component_model: sub_m)
      assert_same odometry, pose.merge(odometry), 'it stands for both'
      assert_same odometry, odometry.merge(pose)
      both = pose.merge(Placeholder.for([MyApp::Cmd], component_model: sub_m))
      assert_equal [MyApp::Pose, MyApp::Cmd].to_set, both.proxied_data_service_models.to_set
      assert_same sub_m, both.proxied_component_model
      assert_raises(IncompatibleComponentModels) { pose.merge(TaskContext.new_submodel) }
    end

    def test_merging_task_models
      sub_m = @task_m.new_submodel
      assert_same sub_m, @task_m.merge(sub_m)
      assert_same sub_m, sub_m.merge(@task_m)
      assert @task_m.can_merge?(sub_m)
      refute sub_m.can_merge?(@task_m)
    end

    def test_specializations_with_different_dynamic_services_cannot_merge
      pose = MyApp::Pose
      odometry = MyApp::Odometry
      task_m = TaskContext.new_submodel do
        output_port 'out', '/double'
        dynamic_service(pose, as: 'dyn') { provides options[:srv] }
      end
      a = task_m.specialize.tap { |m| m.require_dynamic_service('dyn', as: 'srv', srv: pose) }
      b = task_m.specialize.tap { |m| m.require_dynamic_service('dyn', as: 'srv', srv: odometry) }
      c = task_m.specialize.tap { |m| m.require_dynamic_service('dyn', as: 'srv', srv: pose, extra: 1) }
      d = task_m.specialize.tap { |m| m.require_dynamic_service('dyn', as: 'srv', srv: pose) }
      refute a.can_merge?(b)
      refute a.can_merge?(c)
      assert a.can_merge?(d)
      assert a.can_merge?(task_m.specialize)
    end
  end
end
