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
    # Each takes optional actions checked one at a time: devices and
    # definitions (+Base.gps_dev+, 'gps_dev'), requirements made on the spot
    # (+Cmp.use('pose' => Base.gps_dev)+), or whole profiles (every action
    # of +Other+); without any, every device and definition of the profile.
    # As Syskit's, they take +exclude:+ (actions left out) and
    # +together_with:+ (actions added to the network of each one). The
    # +_together+ forms check their actions in one network, and every
    # assertion also has Syskit's +assert_+ name. Failures carry the
    # generator's messages (file:line, hint), as `syskit plan` prints them.
    # As in Syskit, a profile may leave its own tags to the profiles that
    # use it: is_self_contained accepts them (not another profile's), the
    # other assertions do not.
    module ProfileAssertions
      # Each assertion, and the generator step it runs up to.
      STEPS = { is_self_contained: :Instantiate, can_instanciate: :Buses, can_deploy: :Order,
                can_configure: :Connect }.freeze

      STEPS.each do |name, step|
        own_tags = name == :is_self_contained
        define_method(name) do |*actions, exclude: [], together_with: []|
          syskit_check_each(actions, Network.const_get(step), own_tags: own_tags, exclude: exclude,
                                                              together_with: together_with)
        end
        define_method("#{name}_together") do |*actions|
          syskit_check_together(syskit_requirements(actions), Network.const_get(step),
                                own_tags: own_tags, profile: syskit_profile(actions))
        end
        alias_method "assert_#{name}", name
        alias_method "assert_#{name}_together", "#{name}_together"
      end

      private

      # The described profile; else, for assertions given profiles, the
      # first of them.
      def syskit_profile(actions = [])
        desc = self.class.respond_to?(:desc) ? self.class.desc : nil
        profile = desc.respond_to?(:syskit_profile) ? desc.syskit_profile : nil
        profile ||= actions.flatten.find { |a| a.respond_to?(:syskit_profile) }&.syskit_profile
        return profile if profile

        message = "profile assertions need `describe SomeProfile do ... end`, not #{desc.inspect}"
        # A profile whose file did not load leaves its name to whatever
        # else has it (Rock's ::Base, from the base typekit).
        message += ': the profile may not be defined, see the problems of the app' unless Test.app.errors.empty?
        flunk message
      end

      # The requirements +actions+ stand for (every action of the profile
      # when there are none).
      def syskit_requirements(actions)
        actions = actions.flatten
        return syskit_profile.all_requirements if actions.empty?

        actions.flat_map { |action| syskit_action_requirements(action) }
      end

      def syskit_action_requirements(action)
        return action.syskit_profile.all_requirements if action.respond_to?(:syskit_profile)
        return action.all_requirements if action.is_a?(Actions::Profile)
        return [InstanceRequirements.from(action)] if InstanceRequirements.selectable?(action)

        profile = syskit_profile
        [profile.find_action(action) || flunk(Network::Generator.unknown_action(profile, action).report(Test.app.root))]
      end

      def syskit_check_each(actions, through, own_tags:, exclude:, together_with:)
        profile = syskit_profile(actions)
        excluded = syskit_requirements(Array(exclude)) unless Array(exclude).empty?
        together = Array(together_with).empty? ? [] : syskit_requirements(Array(together_with))
        syskit_requirements(actions).each do |req|
          next if excluded&.any? { |e| syskit_same_action?(e, req) }

          syskit_check_together([req, *together], through, own_tags: own_tags, profile: profile)
        end
      end

      def syskit_check_together(requirements, through, own_tags:, profile:)
        app = Test.app
        Network::Generator.new(app, requirements, profile: profile,
                                                  robot_config: app.robot_config(Test.robot)).generate(through: through)
        assert true
      rescue Syskit::Error => e
        flunk e.report(app.root) unless own_tags && UnselectedTag.only_tags_of?(e, profile)
        assert true
      end

      # Whether two requirements are the same action: the same object, or
      # the same device or definition of the same profile.
      def syskit_same_action?(one, other)
        one.equal?(other) || (!one.name.nil? && one.name == other.name && one.profile.equal?(other.profile))
      end
    end
  end
end
