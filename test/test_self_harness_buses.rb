# frozen_string_literal: true

require 'helper'

module Syskit
  # Buses at the level of tasks under Syskit's harness: a bus device's
  # driver task, the devices a bus task serves once attached.
  class TestSelfHarnessBuses < Minitest::Test
    parallelize_me!

    BUS_TEST = <<~RUBY
      require 'syskit/test/self'

      describe 'buses' do
        before do
          bus_m = @bus_m = Syskit::ComBus.new_submodel(name: 'Line', message_type: '/double')
          lamp_m = Syskit::Device.new_submodel(name: 'Lamp')
          Syskit::TaskContext.new_submodel(name: 'LineDriver') do
            dynamic_input_port(/^w\\w+$/, '/double')
            dynamic_output_port(/^\\w+$/, '/double')
            driver_for bus_m, as: 'line'
          end
          Syskit::TaskContext.new_submodel(name: 'LampDriver') do
            input_port 'from_bus', '/double'
            output_port 'to_bus', '/double'
            driver_for lamp_m, as: 'lamp'
            provides bus_m.client_srv, as: 'line_client'
          end
          @line = robot.com_bus bus_m, as: 'line'
          @lamp = robot.device(lamp_m, as: 'lamp').attach_to(@line)
          @other = robot.device(lamp_m, as: 'other')
        end

        it('serves the devices of the tasks attached to it') do
          bus_task = @line.instanciate(plan).to_task
          assert_same @line, bus_task.line_dev
          assert_equal [], bus_task.each_attached_device.to_a
          assert_equal [@lamp], bus_task.attach(@lamp.instanciate(plan))
          assert_equal [], bus_task.attach(@lamp.instanciate(plan))
          assert_equal [], bus_task.attach(@other.instanciate(plan))
          assert_equal [@lamp], bus_task.each_attached_device.to_a
        end

        it('dispatches lazily when told so') do
          refute @bus_m.lazy_dispatch?
          @bus_m.lazy_dispatch = true
          assert @bus_m.lazy_dispatch?
        end
      end
    RUBY

    def test_bus_tasks_serve_the_devices_attached_to_them
      Dir.mktmpdir do |dir|
        write_self_test(dir, 'test_buses.rb', BUS_TEST)
        out, err, = ruby_process('test/test_buses.rb', chdir: dir)
        assert_match(/2 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out, err)
      end
    end
  end
end
