# frozen_string_literal: true

module Syskit
  module Actions
    class Profile
      # What Syskit's profiles answer about themselves, as tests and scripts
      # ask it (+Base.has_definition?('drive')+, +Base.each_tag+...), and the
      # helpers a profile body writes besides its statements (+nothing+,
      # +from(:parent_task)+). Part of the methods of profile modules.
      module Queries
        def has_definition?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
          syskit_profile.has_definition?(name)
        end

        # The definition +name+ ('drive' or 'drive_def'), or nil.
        def find_definition_by_name(name)
          syskit_profile.find_definition(name)
        end

        # A copy of the definition +name+ (see Definitions#definition).
        def definition(name)
          syskit_profile.definition(name)
        end

        def resolved_definition(name)
          syskit_profile.resolved_definition(name)
        end

        # The definitions' requirements, in declaration order.
        def each_definition(&)
          syskit_profile.each_definition(&)
        end

        def has_tag?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
          !syskit_profile.find_tag(name).nil?
        end

        def find_tag(name)
          syskit_profile.find_tag(name)
        end
        alias find_tag_by_name find_tag

        def each_tag(&block)
          return enum_for(__method__) unless block

          syskit_profile.tags.each_value(&block)
        end

        def has_device?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
          !syskit_profile.robot.find_device(name.to_s).nil?
        end

        # The action of device +name+ (+Base.gps_dev+), or nil.
        def find_device_requirements_by_name(name)
          device = syskit_profile.robot.find_device(name.to_s)
          device && syskit_profile.requirement_for(device)
        end

        # Every action (devices' and definitions' requirements), in the order
        # of +action_names+.
        def each_action(&block)
          return enum_for(__method__) unless block

          syskit_profile.action_names.each { |name| yield syskit_profile.find_action(name) }
        end

        # Whether +profile+ was given to use_profile (directly).
        def uses_profile?(profile)
          profile = profile.syskit_profile if profile.respond_to?(:syskit_profile)
          syskit_profile.used_profiles.any? { |(used, _)| used.equal?(profile) }
        end

        # The profile modules given to use_profile, directly.
        def each_used_profile(&block)
          return enum_for(__method__) unless block

          syskit_profile.used_profiles.each { |(used, _)| yield used.namespace }
        end

        # Every profile module used, directly or not, each once.
        def all_used_profiles
          syskit_profile.all_used_profiles.map(&:namespace)
        end

        # Selects nothing for a child (+Cmp.use('pose' => nothing)+): it keeps
        # its own model, an optional child is left out.
        def nothing
          DependencyInjection.nothing
        end

        # Roby's delayed arguments: +from(:parent_task).speed+ passes the
        # composition's argument down to a child (see Compat::DelayedArgument);
        # the others are read at runtime, which this gem does not model.
        def from(object)
          Syskit.app&.not_modelled("from(#{object.inspect}) in profile #{self}", Location.of_caller) unless
            object == :parent_task
          Compat::DelayedArgument.new(object)
        end

        def from_state(state = :state)
          Syskit.app&.not_modelled("from_state in profile #{self}", Location.of_caller)
          Compat::DelayedArgument.new(state)
        end
      end
    end
  end
end
