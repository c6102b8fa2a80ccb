# frozen_string_literal: true

module Syskit
  module Test
    # Assertions on the profile a test describes (+describe Base do ... end+):
    #
    #   it { is_self_contained }   # every device has a model and a single driver
    #   it { can_instanciate }     # drivers, buses and their ports can be set up
    #   it { can_deploy }          # ... and each task has a deployed task
    #   it { can_configure }       # ... and configuration and configure methods apply
    #
    # Each takes optional actions (+Base.gps_dev+ or 'gps_dev') and checks
    # them one at a time; the +_together+ forms check them in one network.
    # Without actions, every device of the profile. Failures carry the
    # generator's messages (file:line, hint), as `syskit plan` prints them.
    # As in Syskit, a profile may leave its own tags to the profiles that
    # use it: is_self_contained accepts them, the other assertions do not.
    module ProfileAssertions
      def is_self_contained(*actions)
        syskit_check_each(actions, Network::Instantiate, own_tags: true)
      end

      def is_self_contained_together(*actions)
        syskit_check_together(actions, Network::Instantiate, own_tags: true)
      end

      def can_instanciate(*actions)
        syskit_check_each(actions, Network::Buses)
      end

      def can_instanciate_together(*actions)
        syskit_check_together(actions, Network::Buses)
      end

      def can_deploy(*actions)
        syskit_check_each(actions, Network::Order)
      end

      def can_deploy_together(*actions)
        syskit_check_together(actions, Network::Order)
      end

      def can_configure(*actions)
        syskit_check_each(actions, Network::Connect)
      end

      def can_configure_together(*actions)
        syskit_check_together(actions, Network::Connect)
      end

      private

      def syskit_profile
        desc = self.class.respond_to?(:desc) ? self.class.desc : nil
        profile = desc.respond_to?(:syskit_profile) ? desc.syskit_profile : nil
        return profile if profile

        message = "profile assertions need `describe SomeProfile do ... end`, not #{desc.inspect}"
        # A profile whose file did not load leaves its name to whatever
        # else has it (Rock's ::Base, from the base typekit).
        message += ': the profile may not be defined, see the problems of the app' unless Test.app.errors.empty?
        flunk message
      end

      def syskit_requirements(actions)
        profile = syskit_profile
        return profile.all_requirements if actions.empty?

        actions.map do |action|
          next action if action.is_a?(InstanceRequirements)

          profile.find_action(action) || flunk(Network::Generator.unknown_action(profile, action).report(Test.app.root))
        end
      end

      def syskit_check_each(actions, through, own_tags: false)
        syskit_requirements(actions).each { |req| syskit_check_together([req], through, own_tags: own_tags) }
      end

      def syskit_check_together(actions, through, own_tags: false)
        requirements = actions.all?(InstanceRequirements) && !actions.empty? ? actions : syskit_requirements(actions)
        app = Test.app
        Network::Generator.new(app, requirements, profile: syskit_profile,
                                                  robot_config: app.robot_config(Test.robot)).generate(through: through)
        assert true
      rescue Syskit::Error => e
        flunk e.report(app.root) unless own_tags && UnselectedTag.only_tags_of?(e, syskit_profile)
        assert true
      end
    end
  end
end
