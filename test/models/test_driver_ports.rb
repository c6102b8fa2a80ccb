# frozen_string_literal: true

require 'helper'

module Syskit
  # driver_for and provides on task models: how a device's or service's
  # ports are bound to the task's, and the errors that say why they cannot
  # be (SPEC 4).
  class TestDriverPorts < Minitest::Test
    DRIVER = <<~RUBY
      module MyApp
        module Devices
          data_service_type 'Pose'
          device_type 'Gps' do
            output_port 'position', '/double'
          end
        end
      end
    RUBY

    # Two ports of the same type, for the Gps's one port.
    GPS_PORTS = "  output_port 'lat', '/double'\n  output_port 'lon', '/double'\n"

    def driver_problem(extension, spec = GPS_PORTS)
      root = my_app(nil, { 'models/devices/gps.rb' => DRIVER,
                           'models/orogen/gps.orogen' => "name 'gps'\ntask_context 'Task' do\n#{spec}end\n",
                           'models/orogen/gps.rb' => "require 'models/devices/gps'\n#{extension}" })
      app = load_app(root, problems: true, everything: true)
      errors = app.problems
      assert_equal 1, errors.size, errors.map { |e| e.report(root) }.join("\n")
      [errors.first, root]
    end

    # An extension that declares the Gps driver without port mappings.
    GPS_DRIVER = "Syskit.extend_model(OroGen.gps.Task) do\n  driver_for MyApp::Devices::Gps, as: 'gps'\nend\n"

    def test_driver_for_with_ambiguous_ports
      error, root = driver_problem(GPS_DRIVER)
      assert_reported error, Regexp.new('gps::Task has several output ports of type /double ' \
                                        'for MyApp::Devices::Gps\'s port \'position\': lat, lon'),
                      at: 'models/orogen/gps.rb:3', hint: /'position' => 'lat'/, root: root
    end

    def test_driver_for_with_no_matching_port
      error, root = driver_problem(GPS_DRIVER, '')
      assert_reported error, %r{gps::Task has no output port of type /double for MyApp::Devices::Gps's port 'position'},
                      at: 'models/orogen/gps.rb:3', root: root
    end

    def test_driver_for_with_ports_of_other_types_lists_them
      error, root = driver_problem(GPS_DRIVER, "  output_port 'fix', '/int32_t'\n  input_port 'cmd', '/double'\n")
      message = "gps::Task has no output port of type /double for MyApp::Devices::Gps's port 'position'; " \
                'its output ports: fix (/int32_t)'
      assert_reported error, Regexp.new(Regexp.escape(message)), at: 'models/orogen/gps.rb:3', root: root
    end

    # oroGen's ro_ptr(T) is not T: the message names the port and the fix.
    def test_driver_for_with_a_read_only_pointer_port
      error, root = driver_problem(GPS_DRIVER, "  output_port 'position', ro_ptr('/double')\n")
      message = "gps::Task's output port 'position' is a /RTT/extras/ReadOnlyPointer</double>, " \
                "not the /double of MyApp::Devices::Gps's port 'position'"
      assert_reported error, Regexp.new(Regexp.escape(message)),
                      at: 'models/orogen/gps.rb:3', hint: %r{with ro_ptr\('/double'\), as the task's is}, root: root
    end

    def test_driver_for_with_an_explicit_mapping
      extension = <<~RUBY
        require 'models/devices/gps'
        Syskit.extend_model(OroGen.gps.Task) do
          driver_for MyApp::Devices::Gps, as: 'gps', 'position' => 'lat'
        end
      RUBY
      root = my_app(nil, { 'models/devices/gps.rb' => DRIVER,
                           'models/orogen/gps.orogen' => "name 'gps'\ntask_context 'Task' do\n#{GPS_PORTS}end\n",
                           'models/orogen/gps.rb' => extension })
      load_app(root, everything: true)
      assert_equal({ 'position' => 'lat' }, OroGen.gps.Task.find_service('gps').port_mappings)
    end

    def test_driver_for_a_data_service
      error, root = driver_problem(<<~RUBY)
        Syskit.extend_model(OroGen.gps.Task) do
          driver_for MyApp::Devices::Pose, as: 'pose'
        end
      RUBY
      assert_reported error, /driver_for expects a device or bus model, got MyApp::Devices::Pose/,
                      at: 'models/orogen/gps.rb:3', hint: /use provides MyApp::Devices::Pose, as: 'name'/, root: root
    end

    def test_provides_without_a_name
      error, root = driver_problem("Syskit.extend_model(OroGen.gps.Task) do\n  provides MyApp::Devices::Pose\nend\n")
      assert_reported error, /provides MyApp::Devices::Pose needs a service name/,
                      at: 'models/orogen/gps.rb:3', hint: /provides MyApp::Devices::Pose, as: 'name'/, root: root
    end

    def test_driver_for_with_an_unknown_option
      error, root = driver_problem(<<~RUBY)
        Syskit.extend_model(OroGen.gps.Task) do
          driver_for MyApp::Devices::Gps, as: 'gps', using: 'x', 'position' => 'lat'
        end
      RUBY
      assert_reported error, /unknown option using:/,
                      at: 'models/orogen/gps.rb:3', hint: /'service_port' => 'task_port'/, root: root
    end

    def test_extend_model_of_something_else
      error, root = driver_problem("Syskit.extend_model(MyApp::Devices::Gps) do\nend\n")
      assert_reported error, /extend_model expects a task model such as OroGen.canbus.Task, got MyApp::Devices::Gps/,
                      at: 'models/orogen/gps.rb:2', root: root
    end
  end
end
