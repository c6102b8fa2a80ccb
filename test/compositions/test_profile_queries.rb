# frozen_string_literal: true

require 'compositions/composition_test_helper'

module Syskit
  # What profiles answer about themselves (Syskit's has_definition?,
  # find_tag, uses_profile?...) and the helpers of profile bodies
  # (nothing, from(:parent_task)).
  class TestProfileQueries < Minitest::Test
    include CompositionTestHelper

    PROFILES = <<~RUBY.freeze
      profile 'Generic' do
        tag 'localization', Services::Pose
        define 'watch', Compositions::Watch.use('pose' => localization_tag)
      end
      profile 'Base' do
      #{ROBOT.lines.map { |l| "  #{l}" }.join}
        use_profile Generic, 'localization' => gps_dev
        use Services::Pose => gps_dev
        define 'blind', Compositions::Watch.use('pose' => nothing)
        define 'tuned', Compositions::Watch.use('follower' => OroGen.rig.Follower.with_arguments(gain: from(:parent_task).gain))
      end
    RUBY

    def setup
      super
      @app = load_rig({ 'models/compositions/watch.rb' => WATCH }, profile: PROFILES,
                                                                   requires: ['models/compositions/watch'])
      @base = Rig::Profiles::Base
      @generic = Rig::Profiles::Generic
    end

    def test_definitions_by_name
      assert @base.has_definition?('watch')
      refute @base.has_definition?('drive')
      assert_same @base.watch_def, @base.find_definition_by_name('watch')
      assert_equal @base.watch_def, @base.definition('watch_def')
      refute_same @base.definition('watch'), @base.definition('watch')
      assert_equal @base.watch_def, @base.resolved_definition('watch')
      assert_nil @base.find_definition_by_name('drive')
      assert_equal %w[watch blind tuned], @base.each_definition.map(&:name)
      assert_equal 'Rig::Profiles::Base.watch_def', @base.watch_def.to_s
    end

    def test_an_unknown_definition_is_a_located_error_listing_the_known_ones
      error = assert_raises(UnknownName) { @base.definition('wach') }
      assert_equal "Rig::Profiles::Base has no definition 'wach' (did you mean 'watch'?)", error.message
      assert_equal 'its definitions: watch, blind, tuned', error.hint
      assert_equal File.expand_path(__FILE__), error.location.path
    end

    def test_tags_devices_and_used_profiles
      assert @generic.has_tag?('localization')
      refute @base.has_tag?('localization')
      assert_same @generic.localization_tag, @generic.find_tag('localization')
      assert_equal [@generic.localization_tag], @generic.each_tag.to_a
      assert @base.has_device?('gps')
      refute @base.has_device?('imu')
      assert_same @base.gps_dev, @base.find_device_requirements_by_name('gps')
      assert_nil @base.find_device_requirements_by_name('imu')
    end

    def test_used_profiles_and_actions
      assert @base.uses_profile?(@generic)
      refute @generic.uses_profile?(@base)
      assert_equal [@generic], @base.each_used_profile.to_a
      assert_equal [@generic], @base.all_used_profiles
      assert_equal %w[gps_dev left_wheel_dev right_wheel_dev watch blind tuned],
                   @base.each_action.map(&:name)
    end

    def test_nothing_and_from_in_a_profile_body
      assert_same DependencyInjection.nothing, @base.blind_def.selections.explicit['pose']
      error = plan_error(@app, 'blind_def')
      assert_match(/the child 'pose' of Rig::Compositions::Watch \(blind.pose\) needs/, error.message)
      assert_equal 'gps', plan_of(@app, 'tuned_def').find_composition('tuned').children['pose']
      assert_equal 'from(:parent_task).gain', @base.tuned_def.selections.explicit['follower'].arguments[:gain].to_s
    end
  end
end
