# frozen_string_literal: true

require 'helper'

module Syskit
  # What provides accepts, as Syskit's data service tests pin it down: a
  # port of the same name must be mapped even when the types agree, a
  # mapping binds to an existing port and never makes one, and service
  # ports sharing one task port must each be mapped on purpose.
  class TestProvidesChecks < Minitest::Test
    def models(source, extra = {})
      root = my_app(nil, { 'models/devices/things.rb' => source }.merge(extra))
      [root, load_app(root, problems: true, everything: true)]
    end

    def single_problem(source, extra = {})
      root, app = models(source, extra)
      assert_equal 1, app.problems.size, app.problems.map { |e| e.report(root) }.join("\n")
      [app.problems.first, root]
    end

    def test_a_port_of_the_same_name_and_type_must_be_mapped
      error, root = single_problem(<<~RUBY)
        module MyApp
          data_service_type('Rate') { output_port 'out', '/double' }
          device_type 'Gyro' do
            output_port 'out', '/double'
            provides Rate
          end
        end
      RUBY
      assert_kind_of SpecError, error, "Syskit's class for a port collision"
      assert_reported error, %r{MyApp::Rate's output port 'out' \(/double\) collides with MyApp::Gyro's output port},
                      at: 'models/devices/things.rb:5',
                      hint: /same port, say so: provides MyApp::Rate, 'out' => 'out'/, root: root
    end

    def test_mapping_a_port_to_itself_shares_it
      _, app = models(<<~RUBY)
        module MyApp
          data_service_type('Rate') { output_port 'out', '/double' }
          device_type 'Gyro' do
            output_port 'out', '/double'
            provides Rate, 'out' => 'out'
          end
        end
      RUBY
      assert_empty app.problems
      assert_equal ['out'], MyApp::Gyro.ports.keys
      assert_equal({ 'out' => 'out' }, MyApp::Gyro.port_mappings_for(MyApp::Rate))
    end

    def test_a_mapping_to_a_port_the_model_lacks_is_an_error_and_adds_no_port
      error, root = single_problem(<<~RUBY)
        module MyApp
          data_service_type('Rate') { output_port 'out', '/double' }
          device_type 'Gyro' do
            provides Rate, 'out' => 'rate'
          end
        end
      RUBY
      assert_kind_of SpecError, error
      assert_reported error, /MyApp::Gyro has no port 'rate' to map MyApp::Rate's output port 'out'/,
                      at: 'models/devices/things.rb:4', hint: %r{declare it before .*output_port 'rate', '/double'},
                      root: root
      assert_empty MyApp::Gyro.ports
    end

    def test_a_mapping_naming_no_port_of_the_provided_model_is_a_spec_error
      error, root = single_problem(<<~RUBY)
        module MyApp
          data_service_type('Rate') { output_port 'out', '/double' }
          device_type 'Gyro' do
            output_port 'rate', '/double'
            provides Rate, 'old' => 'rate'
          end
        end
      RUBY
      assert_kind_of SpecError, error
      assert_reported error, /MyApp::Rate has no port named 'old' or 'rate'/, at: 'models/devices/things.rb:5',
                                                                              hint: /'out' => 'your_port'/, root: root
    end

    def test_a_mapping_to_a_port_of_another_type_or_direction_is_an_error
      ["input_port 'rate', '/double'", "output_port 'rate', '/int32_t'"].each_with_index do |decl, i|
        error, root = single_problem(<<~RUBY)
          module MyApp
            data_service_type('Rate#{i}') { output_port 'out', '/double' }
            device_type 'Gyro#{i}' do
              #{decl}
              provides Rate#{i}, 'out' => 'rate'
            end
          end
        RUBY
        assert_kind_of SpecError, error
        assert_reported error, %r{MyApp::Rate#{i}'s output port 'out' \(/double\) cannot be mapped to MyApp::Gyro#{i}'s},
                        at: 'models/devices/things.rb:5', hint: %r{an output port of type /double}, root: root
        @loaded_apps.pop.unload
      end
    end

    def test_a_mapping_may_bind_a_service_port_to_another_port_than_its_namesake
      _, app = models(<<~RUBY)
        module MyApp
          data_service_type('Count') { output_port 'out', '/int32_t' }
          device_type 'Counter' do
            output_port 'out', '/double'
            output_port 'count', '/int32_t'
            provides Count, 'out' => 'count'
          end
        end
      RUBY
      assert_empty app.problems
      assert_equal '/double', MyApp::Counter.find_port('out').type.name
      assert_equal({ 'out' => 'count' }, MyApp::Counter.port_mappings_for(MyApp::Count))
      assert_equal({ 'out' => 'out', 'count' => 'count' }, MyApp::Counter.port_mappings_for(MyApp::Counter))
    end

    def test_mappings_follow_a_chain_of_provides
      _, app = models(<<~RUBY)
        module MyApp
          data_service_type 'Base' do
            output_port 'base', '/int32_t'
            output_port 'base_only', '/double'
          end
          data_service_type 'Middle' do
            output_port 'middle', '/int32_t'
            output_port 'middle_only', '/double'
            provides Base, 'base' => 'middle'
          end
          data_service_type 'Top' do
            output_port 'top', '/int32_t'
            provides Middle, 'middle' => 'top'
          end
        end
      RUBY
      assert_empty app.problems
      assert_equal({ 'middle' => 'top', 'middle_only' => 'middle_only', 'base_only' => 'base_only' },
                   MyApp::Top.port_mappings_for(MyApp::Middle))
      assert_equal({ 'base' => 'top', 'base_only' => 'base_only' }, MyApp::Top.port_mappings_for(MyApp::Base))
    end

    # A task with one /double output: a service with two /double outputs.
    TWO_OUTPUTS = <<~RUBY
      module MyApp
        module Devices
          device_type 'Pair' do
            output_port 'first', '/double'
            output_port 'second', '/double'
          end
        end
      end
    RUBY

    def task_problem(extension)
      single_problem(TWO_OUTPUTS, 'models/orogen/one.orogen' => ONE_TASK,
                                  'models/orogen/one.rb' => "require 'models/devices/things'\n#{extension}")
    end

    def test_two_service_ports_found_on_one_task_port_are_refused
      %w[driver_for provides].each do |statement|
        error, root = task_problem("Syskit.extend_model(OroGen.one.Task) do\n  " \
                                   "#{statement} MyApp::Devices::Pair, as: 'pair'\nend\n")
        assert_reported error, /Pair's ports first, second would all be bound to one::Task's port 'value'/,
                        at: 'models/orogen/one.rb:3', hint: /map each of them: 'first' => 'value', 'second' => 'value'/,
                        root: root
        @loaded_apps.pop.unload
      end
    end

    def test_one_explicit_mapping_is_not_enough
      error, root = task_problem("Syskit.extend_model(OroGen.one.Task) do\n  " \
                                 "driver_for MyApp::Devices::Pair, as: 'pair', 'first' => 'value'\nend\n")
      assert_reported error, /ports first, second would all be bound/, at: 'models/orogen/one.rb:3', root: root
    end

    ONE_TASK = "name 'one'\ntask_context 'Task' do\n  output_port 'value', '/double'\nend\n"

    def test_every_port_mapped_on_purpose_may_share_a_task_port
      extension = <<~RUBY
        require 'models/devices/things'
        Syskit.extend_model(OroGen.one.Task) do
          driver_for MyApp::Devices::Pair, { 'first' => 'value', 'second' => 'value' }, as: 'pair'
        end
      RUBY
      root, app = models(TWO_OUTPUTS, 'models/orogen/one.orogen' => ONE_TASK, 'models/orogen/one.rb' => extension)
      assert_empty app.problems, app.problems.map { |e| e.report(root) }.join("\n")
      assert_equal({ 'first' => 'value', 'second' => 'value' }, OroGen.one.Task.find_service('pair').port_mappings)
    end
  end
end
