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
      # A profile assertion that does not hold (a test failure, as Syskit's):
      # its message says which action, and the generator's reports.
      class ProfileAssertionFailed < Minitest::Assertion
        # Minitest counts failures by exact class (Assertion): reported as
        # one, so that a run's summary counts it.
        def class
          Minitest::Assertion
        end
      end

      # Each assertion, and the generator step it runs up to.
      STEPS = { is_self_contained: :Instantiate, can_instanciate: :Buses, can_deploy: :Order,
                can_configure: :Connect }.freeze

      STEPS.each do |name, step|
        define_method(name) do |*actions, exclude: [], together_with: []|
          syskit_check_each(actions, name, Network.const_get(step), exclude: exclude, together_with: together_with)
        end
        define_method("#{name}_together") do |*actions|
          requirements = syskit_requirements(actions)
          syskit_check_together(requirements, name, Network.const_get(step), profile: syskit_profile(actions),
                                                                             label: requirements.join(', '))
        end
        alias_method "assert_#{name}", name
        alias_method "assert_#{name}_together", "#{name}_together"
      end

      # Syskit's +Actions(action_or_profile)+: the requirements actions,
      # profiles or requirements stand for, less +exclude:+. Actions of
      # Roby's action interfaces need the runtime: the test skips.
      def Actions(*actions, exclude: []) # rubocop:disable Naming/MethodName -- Syskit's name
        actions.flatten.each { |action| Test.requirements_of(action) }
        excluded = Array(exclude).empty? ? [] : syskit_requirements(Array(exclude))
        syskit_requirements(actions).reject { |req| excluded.any? { |e| syskit_same_action?(e, req) } }
      end

      private

      # The profile the actions are checked in: the first profile among
      # +actions+, else the test's subject (Syskit's +subject_syskit_model+,
      # or the described profile); nil for plain requirements.
      def syskit_profile(actions = [])
        given = actions.flatten.find { |a| a.respond_to?(:syskit_profile) || a.is_a?(Actions::Profile) }
        return syskit_profile_of(given) if given

        desc = self.class.respond_to?(:desc) ? self.class.desc : nil
        syskit_profile_of(desc) || syskit_profile_of(syskit_subject)
      end

      # Syskit's +subject_syskit_model+, when the test has one.
      def syskit_subject
        subject_syskit_model if respond_to?(:subject_syskit_model)
      rescue ArgumentError
        nil
      end

      def syskit_profile_of(object)
        return object if object.is_a?(Actions::Profile)

        object.syskit_profile if object.respond_to?(:syskit_profile)
      end

      # Fails, saying how to name what to check, when there is nothing.
      def syskit_no_profile
        desc = self.class.respond_to?(:desc) ? self.class.desc : nil
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
        return (syskit_profile || syskit_no_profile).all_requirements if actions.empty?

        actions.flat_map { |action| syskit_action_requirements(action) }
      end

      def syskit_action_requirements(action)
        return action.syskit_profile.all_requirements if action.respond_to?(:syskit_profile)
        return action.all_requirements if action.is_a?(Actions::Profile)
        return [InstanceRequirements.from(action)] if InstanceRequirements.selectable?(action)

        profile = syskit_profile || syskit_no_profile
        [profile.find_action(action) || flunk(Network::Generator.unknown_action(profile, action).report(Test.app.root))]
      end

      def syskit_check_each(actions, assertion, through, exclude:, together_with:)
        profile = syskit_profile(actions)
        excluded = syskit_requirements(Array(exclude)) unless Array(exclude).empty?
        together = Array(together_with).empty? ? [] : syskit_requirements(Array(together_with))
        all = syskit_requirements(actions)
        checked = all.reject { |req| excluded&.any? { |e| syskit_same_action?(e, req) } }
        # An assertion that checks nothing would pass whatever the robot:
        # it fails, saying why.
        flunk "#{assertion}: #{actions.flatten.join(', ')} stand for no action" if all.empty? && !actions.flatten.empty?
        syskit_nothing_to_check(assertion, profile, all) if checked.empty?

        checked.each do |req|
          syskit_check_together([req, *together], assertion, through, profile: profile, label: req.to_s)
        end
      end

      def syskit_nothing_to_check(assertion, profile, all)
        if all.empty?
          where = profile.declared_at&.relative_path(Test.app.root)
          flunk "#{assertion}: #{profile.name} has no device and no definition, so there is nothing to check: " \
                "declare the robot's devices#{" in #{where}" if where} (or define what it runs), " \
                'or remove this test'
        end
        flunk "#{assertion}: every action of #{profile.name} is excluded, so there is nothing to check"
      end

      # Generates the network of +requirements+ up to +through+; raises
      # ProfileAssertionFailed with Syskit's words for what failed.
      def syskit_check_together(requirements, assertion, through, profile:, label:)
        app = Test.app
        Network::Generator.new(app, requirements, profile: profile, robot_config: syskit_robot_config)
                          .generate(through: through)
        assert true
      rescue Syskit::Error => e
        if syskit_fails?(e, assertion, profile)
          raise ProfileAssertionFailed, syskit_failure(e, assertion, profile, label)
        end

        assert true
      end

      # The robot configuration deployments come from: the test's own under
      # Syskit's harness, else the app's robot's.
      def syskit_robot_config
        return syskit_test_robot_config if respond_to?(:syskit_test_robot_config)

        Test.app.robot_config(Test.robot)
      end

      # As in Syskit, a profile may leave its own tags to the profiles that
      # use it: is_self_contained accepts them, the other assertions do not.
      def syskit_fails?(error, assertion, profile)
        assertion != :is_self_contained || !UnselectedTag.only_tags_of?(error, profile)
      end

      def syskit_failure(error, assertion, profile, label)
        errors = error.respond_to?(:errors) ? error.errors : [error]
        report = error.report(Test.app.root)
        abstract = errors.grep(TaskAllocationFailed)
        "#{report}\n(#{syskit_summary(errors, abstract, assertion, profile, label)})"
      end

      # What failed, in Syskit's words (its tests match them).
      def syskit_summary(errors, abstract, assertion, profile, label)
        if assertion == :is_self_contained
          others = abstract.grep(UnselectedTag).reject { |e| e.profile.equal?(profile) }
          return "#{label} contains tags from another profile: #{syskit_abstract_names(others)}" if others.any?

          return "#{label} is not self contained"
        end
        return "#{label}: cannot find a concrete implementation for #{syskit_abstract_names(abstract)}" if abstract.any?
        return "#{label}: cannot deploy the following tasks#{syskit_undeployed(errors)}" if errors.any?(DeploymentError)

        "#{label} fails #{assertion}"
      end

      # The tasks without a deployed task, and what needs each (the child
      # roles it fills, the device it drives), as Syskit lists them.
      def syskit_undeployed(errors)
        tasks = errors.grep(DeploymentError).filter_map(&:task).uniq
        return '' if tasks.empty?

        ": #{tasks.map { |task| syskit_undeployed_task(task) }.join('; ')}"
      end

      def syskit_undeployed_task(task)
        needs = task.each_parent_task.flat_map do |parent|
          parent.each_child.select { |child, _| child.equal?(task) }
                .map { |_, info| "child #{info[:role]} of #{parent.model.name}" }
        end
        needs << "the driver of #{task.requirements.device}" if task.requirements&.device
        "#{task.model.name}#{" (#{needs.join(', ')})" unless needs.empty?}"
      end

      # What is abstract, as Syskit names it: +profile:Name.x_tag+ for a
      # tag, +Syskit::Models::Placeholder<Srv>+ for services.
      def syskit_abstract_names(errors)
        errors.map do |e|
          what = e.abstract
          next "profile:#{e.profile&.name}.#{what.name}" if e.is_a?(UnselectedTag)

          models = what.respond_to?(:models) ? what.models : [what]
          next models.join(', ') unless models.all?(Models::DataServiceModel)

          "Syskit::Models::Placeholder<#{models.map(&:name).join(',')}>"
        end.uniq.join(', ')
      end

      # Whether two requirements are the same action: the same object, or
      # the same device or definition of the same profile.
      def syskit_same_action?(one, other)
        one.equal?(other) || (!one.name.nil? && one.name == other.name && one.profile.equal?(other.profile))
      end
    end
  end
end
