# frozen_string_literal: true

require_relative 'composition_test_helper'

module Syskit
  # oroGen's extended state support: every task context of an .orogen
  # file, and every task model made in Ruby, has a +state+ output port
  # (an int32), as in Syskit; a plan shows it only where it is connected.
  class TestStatePort < Minitest::Test
    include CompositionTestHelper

    STATE_WATCH = {
      'models/orogen/watch.orogen' =>
        "name 'watch'\ntask_context 'Counter' do\n  input_port 'states', '/int32_t'\nend\n",
      'models/compositions/state_watch.rb' => <<~RUBY,
        using_task_library 'rig'
        using_task_library 'watch'
        module Rig
          module Compositions
            class StateWatch < Syskit::Composition
              add OroGen.rig.Splitter, as: 'split'
              add OroGen.watch.Counter, as: 'counter'
              split_child.state_port.connect_to counter_child.states_port
            end
          end
        end
      RUBY
      'config/robots/default.rb' => "#{FILES['config/robots/default.rb']}using_task_library 'watch'\n" \
                                    "Syskit.conf.use_deployment OroGen.watch.Counter => 'counter'\n"
    }.freeze

    def test_every_task_context_of_an_orogen_file_has_a_state_port
      load_rig
      port = OroGen.rig.Follower.state_port
      assert port.output?
      assert_equal '/int32_t', port.type.name
      assert_equal %w[command pose state], OroGen.rig.Follower.ports.keys.sort
    end

    def test_every_task_model_made_in_ruby_has_a_state_port
      load_rig
      model = RubyTaskContext.new_submodel { output_port 'out', '/double' }
      assert_equal %w[out state], model.ports.keys.sort
      assert_equal '/int32_t', model.new.state_port.type.name
    end

    def test_a_plan_leaves_out_state_ports_that_are_not_connected
      definition = "define 'follow', Compositions::Follow.use('pose' => gps_dev, #{WHEELS})"
      app = follow_app("profile 'Base' do\n#{ROBOT}#{definition}\nend\n")
      plan = plan_of(app, 'follow_def')
      assert(plan.tasks.none? { |t| t.ports.any? { |p| p.name == 'state' } })
    end

    def test_a_plan_shows_a_state_port_that_is_connected
      app = load_rig(STATE_WATCH, profile: "profile 'Base' do\n  define 'watch', Compositions::StateWatch\nend\n",
                                  requires: ['models/compositions/state_watch'])
      plan = plan_of(app, 'watch_def')
      assert_equal %w[in left right state], plan.tasks.find { |t| t.name == 'splitter' }.ports.map(&:name)
      assert_equal %w[states], plan.tasks.find { |t| t.name == 'counter' }.ports.map(&:name)
      assert_includes connection_lines(plan), 'splitter.state -> counter.states'
    end
  end
end
