# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # Children given to other children with +use+, so that both share one
  # task: a sibling, a child of a child composition (+first_child.src_child+)
  # or a sibling's service (+tracker_child.rear_pose_srv+).
  class TestChildReferences < Minitest::Test
    include CompositionTestHelper

    # A follower of a pose source, and compositions that share sources
    # between two of them.
    CHAIN = <<~RUBY
      require 'models/devices/rover'
      using_task_library 'rig'
      module Rig
        module Compositions
          class Chase < Syskit::Composition
            add Services::Pose, as: 'src'
            add OroGen.rig.Follower, as: 'follower'
            src_child.pose_port.connect_to follower_child.pose_port
          end
          # The second chase follows what the first one follows.
          class Convoy < Syskit::Composition
            add Chase, as: 'lead'
            add(Chase, as: 'tail').use(Services::Pose => lead_child.src_child)
          end
          # Both chases follow one tracker, each through its own service.
          class Pincer < Syskit::Composition
            add OroGen.rig.Tracker, as: 'tracker'
            add(Chase, as: 'front').use('src' => tracker_child.front_pose_srv)
            add(Chase, as: 'rear').use('src' => tracker_child.rear_pose_srv)
          end
        end
      end
    RUBY

    # With +followers+ deployed followers.
    def chain_app(profile, followers: 1)
      robot = FILES['config/robots/default.rb'] +
              (2..followers).map { |i| "Syskit.conf.use_deployment OroGen.rig.Follower => 'follower#{i}'\n" }.join
      follow_app(profile, 'models/compositions/chain.rb' => CHAIN, 'config/robots/default.rb' => robot)
    end

    def test_a_child_composition_s_children_are_reachable_through_it
      load_rig({ 'models/compositions/chain.rb' => CHAIN })
      convoy = Rig::Compositions::Convoy
      src = convoy.lead_child.src_child
      assert_kind_of Models::CompositionChild, src
      assert_same src, convoy.lead_child.find_child('src')
      assert_equal 'lead.src', src.path
      assert_same convoy.lead_child, src.outermost_child
      assert_equal 'Rig::Compositions::Convoy.lead_child.src_child', src.to_s
      assert_equal %w[src follower], convoy.lead_child.child_names
      assert_nil convoy.lead_child.find_child('nothing')
      assert_equal %w[pose], src.ports.keys
    end

    def test_a_grandchild_selected_for_a_child_shares_its_task
      app = chain_app(<<~RUBY)
        require 'models/compositions/chain'
        profile 'Base' do
          define 'convoy', Compositions::Convoy.use('lead.src' => OroGen.rig.Tracker.rear_pose_srv)
        end
      RUBY
      plan = plan_of(app, 'convoy_def')
      assert_equal ['tracker'], plan.tasks.select { |t| t.model == 'rig::Tracker' }.map(&:name)
      assert_equal 'tracker', plan.find_composition('convoy.tail').children['src']
      assert_equal ['tracker.rear -> follower.pose'], connection_lines(plan).uniq
    end

    # A child reached from requirements (+convoy.lead_child+, whose
    # composition model is the requirements) selects that child's task.
    def test_a_child_reached_from_requirements_selects_its_task
      app = chain_app(<<~RUBY)
        require 'models/compositions/chain'
        profile 'Base' do
          convoy = Compositions::Convoy.use('lead.src' => OroGen.rig.Tracker.rear_pose_srv)
          define 'convoy', convoy.use('tail' => convoy.lead_child)
        end
      RUBY
      lead = Rig::Profiles::Base.convoy_def.lead_child
      assert_kind_of InstanceRequirements, lead.composition_model
      plan = plan_of(app, 'convoy_def')
      assert_equal plan.find_composition('convoy.lead').name, plan.find_composition('convoy').children['tail']
      assert_equal ['tracker.rear -> follower.pose'], connection_lines(plan).uniq
    end

    def test_a_sibling_s_service_is_selected_through_that_service
      app = chain_app(<<~RUBY, followers: 2)
        require 'models/compositions/chain'
        profile 'Base' do
          define 'pincer', Compositions::Pincer.use(
            'front.follower' => OroGen.rig.Follower.prefer_deployed_tasks('follower'),
            'rear.follower' => OroGen.rig.Follower.prefer_deployed_tasks('follower2')
          )
        end
      RUBY
      plan = plan_of(app, 'pincer_def')
      followers = plan.tasks.select { |t| t.model == 'rig::Follower' }.map(&:name).sort
      assert_equal 2, followers.size
      lines = connection_lines(plan).sort
      assert_equal 2, lines.size
      assert_match(/\Atracker\.front -> /, lines[0])
      assert_match(/\Atracker\.rear -> /, lines[1])
    end

    def test_a_grandchild_s_ports_are_not_connected_from_the_outer_composition
      load_rig({ 'models/compositions/chain.rb' => CHAIN })
      model = Composition.new_submodel do
        add Rig::Compositions::Chase, as: 'chase'
        add OroGen.rig.Tracker, as: 'tracker'
      end
      error = assert_raises(DeclarationError) do
        model.chase_child.src_child.pose_port.connect_to model.chase_child.follower_child.pose_port
      end
      assert_match(/chase_child.src_child.pose_port is a port of a child of the child composition/, error.message)
      assert_match(/export it from Rig::Compositions::Chase/, error.hint)
      assert_equal 1, Rig::Compositions::Chase.port_connections.size
    end

    def test_a_grandchild_s_port_is_no_port_of_the_outer_composition
      load_rig({ 'models/compositions/chain.rb' => CHAIN })
      model = Composition.new_submodel do
        add Rig::Compositions::Chase, as: 'chase'
        add OroGen.rig.Tracker, as: 'tracker'
      end
      follower_in = model.chase_child.follower_child.pose_port
      error = assert_raises(DeclarationError) { model.tracker_child.front_port.connect_to follower_in }
      assert_match(/is not a port of a child of/, error.message)
      refute model.child_port?(follower_in)
      assert_raises(DeclarationError) { model.export follower_in }
    end

    def test_a_misspelled_grandchild_is_explained
      app = load_app(rig_app({ 'models/compositions/chain.rb' => CHAIN, 'models/compositions/bad.rb' => <<~RUBY }),
        require 'models/compositions/chain'
        module Rig
          module Compositions
            class Bad < Syskit::Composition
              add Chase, as: 'lead'
              add(Chase, as: 'tail').use(Services::Pose => lead_child.folower_child)
            end
          end
        end
      RUBY
                     problems: true)
      error = app.errors.find { |e| e.message.include?('folower') }
      assert_match(/Bad.lead_child has no child 'folower'.*did you mean 'follower'/, error.message)
      assert_equal 'its children: src, follower', error.hint
    end
  end
end
