# frozen_string_literal: true

require 'helper'

module Syskit
  # A task's properties as Syskit gives them: Property objects
  # (task.property, task.<name>_property, properties['name']) and accessors
  # on task.properties that convert values to the property's type.
  class TestTaskProperties < Minitest::Test
    include SelfTest::ModelsMadeInRuby

    def setup
      super
      @task_m = TaskContext.new_submodel do
        property 'gain', '/double', 2
        property 'test', '/int32_t'
      end
      @task = @task_m.new
    end

    def test_a_task_has_a_property_object_per_declared_property
      gain = @task.property('gain')
      assert_kind_of Property, gain
      assert_equal 'gain', gain.name
      assert_same @task, gain.task_context
      assert_same Syskit.app.types.find('/double'), gain.type
      assert_in_delta 2.0, gain.value
      assert_same gain, @task.property(:gain)
      assert_same gain, @task.gain_property
      assert_same gain, @task.properties['gain']
      assert_equal [gain, @task.test_property], @task.each_property.to_a
    end

    def test_a_missing_property_is_nil_in_properties_and_an_error_on_the_task
      assert_nil @task.properties['gian']
      refute @task.properties.include?('gian')
      assert @task.properties.include?(:gain)
      refute @task.has_property?('gian')
      error = assert_raises(Compat::Orocos::InterfaceObjectNotFound) { @task.property('gian') }
      assert_match(/has no property 'gian'.*gain/, error.message)
    end

    def test_accessors_write_values_converted_to_the_property_type
      @task.properties.gain = 3
      assert_in_delta 3.0, @task.properties.gain
      assert_kind_of Float, @task.property('gain').read
      @task.properties.raw_gain = 4
      assert_in_delta 4.0, @task.properties.raw_gain
      @task.properties.gain { |value| value * 2 }
      assert_in_delta 8.0, @task.properties.gain
      error = assert_raises(ConfigurationError) { @task.properties.gain = 'fast' }
      assert_match(/property 'gain' of/, error.message)
    end

    def test_a_property_named_like_a_private_kernel_method_has_accessors
      @task.properties.test = 10
      assert_equal 10, @task.properties.test
    end

    def test_properties_made_from_property_objects_have_their_accessors
      property = Property.new(Orogen::Property.new('rate', Syskit.app.types.find('/double'), 1), @task_m)
      properties = Properties.new(nil, 'rate' => property)
      assert_same property, properties['rate']
      properties.rate = 5
      assert_in_delta 5.0, property.value
      refute_respond_to Properties.new(nil, {}), :rate
    end

    def test_raw_values_made_by_typelib_are_of_the_property_type
      raw = Typelib.from_ruby(10, @task.gain_property.type)
      @task.properties.raw_gain = raw
      assert_in_delta 10.0, @task.properties.raw_gain
    end

    def test_the_configuration_manager_is_the_concrete_model_s_configuration
      manager = @task_m.configuration_manager
      assert_same manager, @task_m.specialize.configuration_manager
      assert_same manager, @task_m.configuration_manager
      assert_empty manager.section_names
      Syskit.app.stub_conf(@task_m, ['default'], { 'gain' => 3 }, Location.of_caller)
      assert_equal ['default'], @task_m.configuration_manager.section_names
    ensure
      Syskit.app.clear_conf_stubs
    end

    def test_what_a_running_component_says_of_a_task_skips_the_test_asking_it
      require 'syskit/test/runtime_only'
      Test::RuntimeOnly::TASK_METHODS.each do |name|
        skip = assert_raises(Minitest::Skip) { @task.public_send(name) }
        assert_equal "task.#{name} needs Syskit's runtime (Roby and Orocos)", skip.message
      end
    end
  end
end
