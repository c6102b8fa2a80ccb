# frozen_string_literal: true

module Syskit
  module Network
    # The plan of a whole profile on a robot: its devices and its
    # definitions in one network.
    #
    # Definitions are what the robot can run, not all at once (two may
    # command the same arm). When they cannot all be planned together but
    # the devices plan and each definition plans on its own (as syskit check
    # plans them), the plan is the devices' and #apart holds the problems of
    # planning everything together. A definition that only misses what the
    # profile's own tags stand for plans in the profiles that select them.
    class ProfilePlan
      attr_reader :plan, :apart, :profile

      def initialize(app, profile, robot: 'default')
        @app = app
        @profile = profile
        @robot_config = app.robot_config(robot)
        @apart = nil
        @plan = plan_whole
      end

      # True when the plan is the devices' only (see #apart).
      def apart?
        !@apart.nil?
      end

      # What a command says when the plan is the devices' only.
      def apart_warning
        first = apart.first
        Warning.new("#{why_apart} (the first: #{first.message}); this is the plan of its devices",
                    location: first.location,
                    hint: "#{plan_one_hint} (its definitions: #{definition_names.join(', ')})")
      end

      private

      def plan_whole
        generate(profile.all_requirements)
      rescue Syskit::Error => e
        raise e unless (plan = plan_apart)

        @apart = e.is_a?(ErrorList) ? e.errors : [e]
        plan
      end

      def why_apart
        return "#{profile.name} leaves what its tags stand for to the profiles using it" if generic?

        "the #{definition_names.size} definitions of #{profile.name} cannot all run at once: " \
          "#{Naming.count(apart.size, 'problem')} when planned together"
      end

      def plan_one_hint
        command = "syskit plan #{profile.name} #{definition_names.first}"
        return "plan a profile that selects them, or one definition: #{command}" if generic?

        "plan one definition at a time: #{command}"
      end

      def generic?
        UnselectedTag.only_tags_of?(ErrorList.new(apart), profile)
      end

      def definition_names
        profile.definitions.keys.map { |name| "#{name}_def" }
      end

      def plan_apart
        return if profile.definitions.empty?

        devices = generate(profile.device_requirements)
        devices if profile.definition_requirements.all? { |d| plans_alone?(d) }
      rescue Syskit::Error
        nil
      end

      def plans_alone?(definition)
        generate([definition])
        true
      rescue Syskit::Error => e
        UnselectedTag.only_tags_of?(e, profile)
      end

      def generate(requirements)
        Generator.new(@app, requirements, profile: profile, robot_config: @robot_config).generate.plan
      end
    end
  end
end
