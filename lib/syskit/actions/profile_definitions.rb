# frozen_string_literal: true

module Syskit
  module Actions
    class Profile
      # A tag: a placeholder for a component that a profile using this one
      # chooses (+tag 'localization', Services::Pose+ gives
      # +Base.localization_tag+; +use_profile Base, 'localization' => X+
      # selects it).
      class Tag
        # What tasks standing for a tag have: one stands only for tasks of
        # the same tag (not for those of another tag of the same services).
        module Task
          def can_merge?(other)
            super && other.model.equal?(model)
          end
        end

        # The kind of placeholder models tags have (see #placeholder_model).
        PLACEHOLDER = Syskit::Models::Placeholder.new_specialized_placeholder(task_extension: Task)

        attr_reader :profile, :name, :models, :declared_at

        def initialize(profile, name, models, location)
          @profile = profile
          @name = name
          @models = models.freeze
          @declared_at = location
          @placeholder_model = nil
        end

        # The placeholder model of the tag's tasks, its own (as Syskit's
        # tags): tasks of two tags of the same services are of two models,
        # so that neither can stand for the other.
        def placeholder_model
          @placeholder_model ||= PLACEHOLDER.create_for(models, as: to_s)
        end

        # The requirements it stands for (abstract: only services).
        def requirements
          InstanceRequirements.new([placeholder_model], profile: profile, name: "#{name}_tag", declared_at: declared_at)
        end

        # Tasks standing for the tag in +plan+ (see
        # InstanceRequirements#instanciate).
        def instanciate(plan, ...)
          requirements.instanciate(plan, ...)
        end

        def each_fullfilled_model(&)
          requirements.each_fullfilled_model(&)
        end

        def fullfills?(model)
          requirements.fullfills?(model)
        end

        def to_s
          "#{profile}.#{name}_tag"
        end
        alias inspect to_s
      end

      # What a profile defines besides its robot, as Syskit's profiles:
      # definitions (+define 'arm_control', Cmp.use(arm_dev)+, then
      # +Base.arm_control_def+), tags, the profiles it uses and its own
      # dependency injection (+use Services::Pose => OroGen.gps.Task+).
      module Definitions
        TRANSFORM_EXAMPLE = "transform_names: ->(name) { \"left_\#{name}\" }"

        # Definitions by name, in declaration order (those of used profiles
        # first, the profile's own overriding them).
        def definitions
          @definitions ||= {}
        end

        def tags
          @tags ||= {}
        end

        # The profiles used with use_profile, with their tag selections and
        # where each was used.
        def used_profiles
          @used_profiles ||= []
        end

        # The profile's own +use+ selections.
        def selections
          @selections || DependencyInjection::EMPTY
        end

        # Defines +name_def+: +requirements+ under the name +name+ (see
        # Definition), returned.
        def define(name, requirements, location: Location.of_caller, doc: nil)
          name = Arguments.name(name, statement: 'define', what: 'a definition name', pattern: Arguments::METHOD_NAME,
                                      example: "define 'arm_control', Compositions::ArmControl")
          return not_modelled_definition(name, location, requirements.to_s) if Compat::Ignored === requirements # rubocop:disable Style/CaseEquality

          unless InstanceRequirements.selectable?(requirements)
            raise DeclarationError.new(
              "define '#{name}' expects a model, a device or requirements, got #{Arguments.shown(requirements)}",
              location: location, hint: "write define '#{name}', Compositions::X.use('child' => Base.x_dev)"
            )
          end

          requirements = dependency_injection_context.direct_selection_for(requirements) || requirements
          requirements = InstanceRequirements.from(requirements, location: location)
          missing = requirements.selections.not_modelled.first
          return not_modelled_definition(name, location, missing[0]) if missing

          register_definition(name, requirements, doc, location)
        end

        # A definition of something not modelled, or that selects something
        # not modelled (+what+, as the device of use_gazebo_model): one
        # warning, and the definition is left out of the plan; its action
        # stands for it, so that later statements may refer to it.
        def not_modelled_definition(name, location, what)
          what = 'something not modelled' if what == Compat::Ignored.instance.to_s
          value = Compat::Ignored.new(what)
          Syskit.app&.not_modelled("definition '#{name}', which depends on #{what}", location)
          define_action("#{name}_def") { value }
          value
        end

        def register_definition(name, requirements, doc, location)
          definition = requirements.named(name, self, location, doc: doc)
          definitions[name] = definition
          define_definition_action(name)
          definition
        end

        # The definition +name+ ('arm_control' or 'arm_control_def').
        def find_definition(name)
          definitions[name.to_s.delete_suffix('_def')]
        end
        alias find_definition_by_name find_definition

        # A copy of the definition +name+ ('drive' or 'drive_def'; Syskit's
        # +definition+), a new one each time; an UnknownName error naming
        # the known ones when there is none. Its requirements are resolved
        # in this profile (its selections, devices and tags) when they are
        # instantiated: +resolved_definition+ is the same.
        def definition(name)
          found = find_definition(name)
          return found.dup if found

          known = definitions.keys
          raise UnknownName.new("#{self} has no definition '#{name}'#{Naming.did_you_mean(name.to_s, known)}",
                                location: Location.of_caller,
                                hint: known.empty? ? "#{self} defines none" : "its definitions: #{known.join(', ')}")
        end
        alias resolved_definition definition

        def has_definition?(name) # rubocop:disable Naming/PredicatePrefix -- Syskit's name
          definitions.key?(name.to_s.delete_suffix('_def'))
        end

        def each_definition(&block)
          return enum_for(__method__) unless block

          definitions.each_value(&block)
        end

        def tag(name, *models, location: Location.of_caller)
          name = Arguments.name(name, statement: 'tag', what: 'a tag name', pattern: Arguments::METHOD_NAME,
                                      example: "tag 'localization', Services::Pose")
          models = models.flatten
          if models.empty? || !models.all? { |m| m.is_a?(Syskit::Models::DataServiceModel) || (m.is_a?(Class) && m < Component) }
            raise DeclarationError.new("tag '#{name}' expects data service or component models",
                                       location: location, hint: "write tag '#{name}', Services::Pose")
          end

          tag = Tag.new(self, name, models, location)
          tags[name] = tag
          define_action("#{name}_tag") { tag }
          tag
        end

        def find_tag(name)
          tags[name.to_s.delete_suffix('_tag')]
        end

        # Adds selections every definition of the profile uses.
        def use(*mappings)
          @selections = selections.dup.add(*mappings).freeze
          @dependency_injection_context = nil
          self
        end

        # Uses +profile+: its devices, definitions and selections become this
        # profile's; +tags+ select components for its tags (by tag name or
        # tag object); +transform_names+, when given, names each definition
        # here from its name there.
        def use_profile(profile, tags = {}, location: Location.of_caller, transform_names: nil)
          profile = profile.syskit_profile if profile.respond_to?(:syskit_profile)
          unless profile.is_a?(Profile)
            raise DeclarationError.new("use_profile expects a profile, got #{Arguments.shown(profile)}",
                                       location: location, hint: 'write use_profile Profiles::Base')
          end

          tag_selections = resolve_tag_selection(profile, tags, location)
          used_profiles << [profile, tag_selections, location]
          robot.use_robot(profile.robot)
          # Its devices are this profile's actions too (Importer.gps_dev).
          profile.robot.each_master_device { |device| define_device_action(device) }
          profile.definitions.each_value do |definition|
            requirements = definition
            requirements = requirements.use(tag_selections) unless tag_selections.empty?
            name = transformed_name(definition.name, transform_names, location)
            register_definition(name, requirements, definition.doc, definition.declared_at)
          end
          @dependency_injection_context = nil
          self
        end

        # What the profile's definitions are instantiated with: its robot's
        # devices (a device model with a single device selects it), the
        # selections of the profiles it uses, then its own.
        def dependency_injection_context
          @dependency_injection_context ||= begin
            context = DependencyInjectionContext::EMPTY.with(robot_injection)
            all_used_profiles.each { |p| context = context.with(p.selections) }
            context.with(selections)
          end
        end

        # Where this profile uses +other+: its use_profile statement of
        # +other+, or of the profile through which it uses +other+.
        def use_profile_location(other)
          used_profiles.each do |(profile, _tags, location)|
            return location if profile.equal?(other) || profile.all_used_profiles.include?(other)
          end
          nil
        end

        # Every profile used, directly or not, each once.
        def all_used_profiles(found = [])
          used_profiles.each do |(profile, _tags)|
            next if found.include?(profile)

            found << profile
            profile.all_used_profiles(found)
          end
          found
        end

        private

        def robot_injection
          by_model = robot.each_master_device.group_by(&:model)
          selected = by_model.filter_map do |model, devices|
            [model, requirement_for(devices.first)] if devices.size == 1
          end
          DependencyInjection.of(selected.to_h)
        end

        def resolve_tag_selection(profile, tags, location)
          tags.to_h do |key, value|
            tag = key.is_a?(Tag) ? key : profile.find_tag(key)
            raise unknown_tag(profile, key, location) unless tag

            [tag, value]
          end
        end

        # The name a used profile's definition +name+ gets here.
        def transformed_name(name, transform, location)
          return name unless transform

          unless transform.respond_to?(:call)
            raise DeclarationError.new(
              "use_profile's transform_names expects a block, got #{Arguments.shown(transform)}",
              location: location, hint: "write #{TRANSFORM_EXAMPLE}"
            )
          end

          result = transform.call(name)
          Arguments.name(result.to_s, statement: 'use_profile', what: 'a definition name from transform_names',
                                      pattern: Arguments::METHOD_NAME,
                                      example: "use_profile Arm, #{TRANSFORM_EXAMPLE}")
        end

        def unknown_tag(profile, key, location)
          known = profile.tags.keys
          DeclarationError.new(
            "#{profile.name} has no tag '#{key}'#{Naming.did_you_mean(key.to_s, known)}",
            location: location,
            hint: known.empty? ? "#{profile.name} declares no tags" : "its tags: #{known.join(', ')}"
          )
        end

        def define_definition_action(name)
          definitions = self.definitions
          define_action("#{name}_def") { definitions.fetch(name) }
        end

        # A method of the profile module (+Base.arm_control_def+).
        def define_action(method_name, &)
          namespace.define_singleton_method(method_name, &)
        end
      end
    end
  end
end
