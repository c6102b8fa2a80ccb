# frozen_string_literal: true

require_relative 'generator_test_helper'

module Syskit
  # Syskit's two configuration hooks in a plan: update_properties (the
  # newer one) runs after the configuration sections and before configure;
  # a model that defines configure alone gets update_properties from
  # configure's super.
  class TestUpdateProperties < Minitest::Test
    include GeneratorTestHelper

    # sensor::Task's threshold: 2.5 from its default section, then what the
    # hooks of +body+ (Ruby in Syskit.extend_model OroGen.sensor.Task) set.
    def sensor_plan(body)
      files = { 'config/orogen/sensor::Task.yml' => "--- name:default\nthreshold: 2.5\n",
                'models/orogen/sensor.rb' => <<~RUBY }
                  require 'models/devices/imu'
                  Syskit.extend_model OroGen.sensor.Task do
                    driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'
                  #{body.gsub(/^/, '  ')}
                  end
                RUBY
      generate(on_can0, files).plan
    end

    def test_update_properties_sets_properties_after_the_sections
      plan = sensor_plan(<<~RUBY)
        def update_properties
          super
          properties.threshold = properties.threshold * 10 + sensor_dev.name.size
        end
      RUBY
      assert_equal 26.0, plan.find_task('a').properties['threshold']
    end

    def test_configure_sees_what_update_properties_set
      plan = sensor_plan(<<~RUBY)
        def update_properties
          super
          properties.threshold = 4.0
        end

        def configure
          super
          properties.threshold += 1
        end
      RUBY
      assert_equal 5.0, plan.find_task('b').properties['threshold']
    end

    # An update_properties of a module (a plugin's), which does not count
    # for use_update_properties?.
    MODULE_UPDATE_PROPERTIES = <<~RUBY
      prepend(Module.new do
        def update_properties
          super
          properties.threshold = 7.0
        end
      end)
    RUBY

    def test_update_properties_of_a_module_runs_through_configure_s_super
      plan = sensor_plan(MODULE_UPDATE_PROPERTIES + <<~RUBY)
        def configure
          super
          properties.threshold += 1
        end
      RUBY
      assert_equal 8.0, plan.find_task('a').properties['threshold']
    end

    def test_configure_without_super_does_not_run_update_properties
      plan = sensor_plan(MODULE_UPDATE_PROPERTIES + <<~RUBY)
        def configure
          properties.threshold += 1
        end
      RUBY
      assert_equal 3.5, plan.find_task('a').properties['threshold']
    end

    def test_an_error_in_update_properties_is_located_and_named
      error = generation_error(on_can0, 'models/orogen/sensor.rb' => <<~RUBY).first
        require 'models/devices/imu'
        Syskit.extend_model OroGen.sensor.Task do
          driver_for MyApp::Devices::TemperatureSensor, as: 'sensor'
          def update_properties
            properties.threshhold = 2
          end
        end
      RUBY
      assert_match(/in sensor::Task's update_properties for device 'a': .*no property 'threshhold'/, error.message)
      assert_equal [File.join(@root, 'models/orogen/sensor.rb'), 5], [error.location.path, error.location.lineno]
      assert_equal 'its properties are limits, threshold', error.hint
    end
  end
end
