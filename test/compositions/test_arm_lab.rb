# frozen_string_literal: true

require 'helper'

module Syskit
  # The second example app, examples/arm_lab: compositions and profiles as
  # Syskit users write them, which the compositions guide shows (its
  # tests run with rake test in TestHarness).
  class TestArmLab < Minitest::Test
    ARM_LAB = File.join(GEM_ROOT, 'examples', 'arm_lab')

    def test_check_passes
      out, err, status = run_cli('check', '--app', ARM_LAB)
      assert_equal 0, status, "#{out}#{err}"
      assert_equal "ArmLab: 0 error(s), 0 warning(s)\n", out
    end

    # Lab leaves its target tag to the profiles using it: Bench selects it,
    # so that every definition plans there.
    def test_every_definition_plans_where_its_tags_are_selected
      app = load_app(ARM_LAB)
      bench = app.profiles.fetch('ArmLab::Profiles::Bench')
      names = bench.definitions.keys
      assert_equal %w[right_hold right_hold_gentle follow_wand reach_target], names
      names.each do |name|
        plan = Network::Generator.plan_profile(app, bench, actions: ["#{name}_def"]).plan
        assert_equal name, plan.compositions.first.name
      end
    end

    # What the compositions guide says of the selections in the app.
    def test_selection_rules_the_guide_states
      app = load_app(ARM_LAB)
      lab = ArmLab::Profiles::Lab
      # By name before by model: Reach's own use('controller' => ...) wins
      # over the profile's use(Services::JointsController => ...).
      assert_equal 'arm_control::CartesianController', controller_of(app, lab.follow_wand_def)
      assert_equal 'arm_control::JointPositionController', controller_of(app, lab.right_hold_def)
      # Two defaults providing Services::Pose select neither.
      ambiguous = ArmLab::Compositions::Reach.use(lab.wand_dev, OroGen.arm_control.WaypointPlayer,
                                                  'control.arm' => lab.left_arm_dev)
      error = assert_raises(NetworkError) { plan(app, ambiguous) }
      assert_match(/\Athe child 'target' of ArmLab::Compositions::Reach .* nothing selects/, error.message)
    end

    private

    def plan(app, requirements)
      Network::Generator.new(app, [requirements], profile: ArmLab::Profiles::Lab.syskit_profile,
                                                  robot_config: app.robot_config('default')).generate.plan
    end

    def controller_of(app, definition)
      plan = plan(app, definition)
      name = plan.compositions.find { |c| c.children.key?('controller') }.children['controller']
      plan.tasks.find { |t| t.name == name }.model
    end
  end
end
