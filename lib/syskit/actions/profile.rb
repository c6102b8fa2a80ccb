# frozen_string_literal: true

require 'syskit/actions/profile_definitions'
require 'syskit/actions/profile/queries'
require 'syskit/actions/profile/definition'

module Syskit
  module Actions
    # A profile: a module with a robot definition and definitions. Each
    # device declared in its robot block gives the profile an action,
    # +Base.gps_dev+, that stands for the device's driver in plans and tests;
    # each definition one too, +Base.arm_control_def+.
    #
    # Both forms of the seed define one:
    #
    #   profile 'Base' do robot do ... end end
    #   module Base; robot do ... end; end
    class Profile
      include Definitions

      attr_reader :namespace, :robot, :declared_at

      # The profiles made by the profile statement or with +register: true+
      # (the modules, for profiles of modules), as Syskit's
      # +Profile.each_submodel+. Held weakly: a profile of an unloaded app
      # goes with it.
      def self.each_submodel(&block)
        return enum_for(__method__) unless block

        registered.each_key(&block)
      end

      def self.register_submodel(profile)
        registered[profile] = true
      end

      def self.registered
        @registered ||= ObjectSpace::WeakMap.new
      end
      private_class_method :registered

      # The profile of +mod+, making it one if it is not yet.
      def self.for_module(mod, location)
        existing = mod.instance_variable_get(:@syskit_profile)
        return existing if existing

        profile = new(namespace: mod, location: location)
        mod.instance_variable_set(:@syskit_profile, profile)
        mod.extend(ModuleMethods)
        register_submodel(mod)
        Syskit.app&.register_profile(profile)
        profile
      end

      # A profile named +name+ (Syskit's +Profile.new(name, register:)+),
      # its actions methods of its own (+profile.x_def+); or the profile
      # of the module +namespace+, whose actions are the module's methods.
      def initialize(name = nil, register: false, namespace: nil, location: Location.of_caller)
        @given_name = name
        @namespace = namespace || self
        @declared_at = location
        # A profile made in Ruby declares its devices on its robot
        # (+profile.robot.device(...)+), as Syskit's.
        @robot = namespace ? Robot::Definition.new(self) : Robot::RobotDefinition.new(self)
        @deployment_group = Syskit::Models::DeploymentGroup.new
        Profile.register_submodel(self) if register
      end

      # The deployments of the profile's actions (Syskit's deployment
      # group): their tasks are deployed from them before the robot's.
      attr_reader :deployment_group

      # Deployments for the profile's actions, as in config/robots
      # (see Models::DeploymentGroup):
      #
      #   use_deployment OroGen.rig.Tracker => 'rear_tracker'
      DEPLOYMENT_STATEMENTS = %i[use_deployment use_deployments_from use_ruby_tasks use_unmanaged_task use_group].freeze

      DEPLOYMENT_STATEMENTS.each do |statement|
        define_method(statement) do |*args, **options|
          deployment_group.public_send(statement, *args, **options)
          self
        end
      end

      # A deployment group of its own, +<name>_deployment_group+, for
      # use_group (here, or in requirements' use_deployment_group):
      #
      #   define_deployment_group 'trackers' do
      #     use_deployment OroGen.rig.Tracker => 'rear_tracker'
      #   end
      #   use_group trackers_deployment_group
      def define_deployment_group(name, &block)
        group = Syskit::Models::DeploymentGroup.new
        group.instance_eval(&block) if block
        define_action("#{name}_deployment_group") { group }
        group
      end

      def name
        namespace.equal?(self) ? @given_name : namespace.name
      end

      def to_s
        name || 'anonymous profile'
      end
      alias inspect to_s

      # Evaluates a robot block.
      def robot_block(&block)
        robot.declaring { Robot::DSL.new(robot).instance_eval(&block) } if block
        robot
      end

      # Defines +<device>_dev+ on the profile module: one shared method
      # under the action's name, which finds the device from the name it is
      # called by. (Defined from the method itself rather than aliased:
      # an alias, made public, costs one more object per device.)
      def define_device_action(device)
        action = "#{device.name}_dev"
        return define_singleton_method(action) { find_action(action) } if namespace.equal?(self)

        namespace.singleton_class.send(:define_method, action, ModuleMethods::DEVICE_ACTION)
      end

      # Action names (+gps_dev+, ...), in declaration order, each device's
      # slaves after it (+stereo.left_dev+), then the definitions (+x_def+).
      def action_names
        devices = robot.each_master_device.flat_map do |device|
          ["#{device.name}_dev", *device.each_slave.map { |slave| "#{slave.full_name}_dev" }]
        end
        devices + definitions.keys.map { |name| "#{name}_def" }
      end

      # The requirements of action +name+ ('gps_dev', or the device name
      # 'gps'; 'arm_control_def' or 'arm_control'), the same object every
      # time. The action of a device named 'gps_dev' is 'gps_dev_dev'.
      def find_action(name)
        name = name.to_s
        return find_definition(name) if name.end_with?('_def') && has_definition?(name)

        device = (robot.find_device(name.delete_suffix('_dev')) if name.end_with?('_dev')) || robot.find_device(name)
        return requirement_for(device) if device

        find_definition(name)
      end

      # The requirements of every device and definition, for plans of the
      # whole profile.
      def all_requirements
        device_requirements + definition_requirements
      end

      def device_requirements
        robot.each_master_device.map { |d| requirement_for(d) }
      end

      def definition_requirements
        definitions.values
      end

      # The action of +device+ (see InstanceRequirements): left unfrozen, so
      # that its slaves' actions can be added to it (+stereo_dev.left_dev+).
      def requirement_for(device)
        (@requirements ||= {}.compare_by_identity)[device] ||= begin
          requirement = InstanceRequirements.new(device: device, profile: self, name: "#{device.full_name}_dev",
                                                 declared_at: device.declared_at, open: true)
          device.each_slave { |slave| define_slave_action(requirement, slave) }
          requirement
        end
      end

      # Called when +slave+ is registered on its master: the master's action
      # gains +<slave>_dev+ (+Base.stereo_dev.left_dev+).
      def slave_registered(slave)
        requirement = @requirements && @requirements[slave.master_device]
        define_slave_action(requirement, slave) if requirement
      end

      def define_slave_action(requirement, slave)
        profile = self
        requirement.define_singleton_method("#{slave.name}_dev") { profile.requirement_for(slave) }
      end

      # Profile statements about simulation and the transformer: accepted,
      # with a "not modelled" warning each (see Compat). The value says which
      # action name a statement defines, when it defines one, so that later
      # statements can refer to it.
      # +use_sdf_model model, as: 'arm'+ makes +arm_dev+ from the SDF model,
      # which is not modelled either.
      NOT_MODELLED = { use_sdf_world: nil, use_sdf_model: ->(*, as: nil, **) { "#{as}_dev" if as },
                       transformer: nil }.freeze

      # The comment block above +location+ (documentation of a statement).
      def self.doc_above(location)
        (@doc_comments ||= Robot::DocComment.new).above(location)
      end

      # Methods of profile modules.
      module ModuleMethods
        include Queries

        NOT_MODELLED.each do |statement, action|
          define_method(statement) do |*args, **options, &_block|
            Syskit.app&.not_modelled("#{statement} in profile #{self}", Location.of_caller)
            name = action&.call(*args, **options)
            value = Compat::Ignored.instance
            if name && !respond_to?(name)
              value = Compat::Ignored.new("#{self}.#{name} (made by #{statement})")
              define_singleton_method(name) { value }
            end
            value
          end
        end

        def robot(&)
          syskit_profile.robot_block(&)
        end

        [*DEPLOYMENT_STATEMENTS, :define_deployment_group].each do |statement|
          define_method(statement) do |*args, **options, &block|
            result = syskit_profile.public_send(statement, *args, **options, &block)
            result.equal?(syskit_profile) ? self : result
          end
        end

        # Defines +name_def+: what the robot can run (see Definitions#define).
        # The comment block above the statement documents it.
        def define(name, requirements)
          location = Location.of_caller
          syskit_profile.define(name, requirements, location: location, doc: Profile.doc_above(location))
        end

        def tag(name, *models)
          syskit_profile.tag(name, models, location: Location.of_caller)
        end

        def use(*mappings)
          syskit_profile.use(*mappings)
          self
        end

        # rock_gazebo's statement: the model's device (see Compat::Gazebo),
        # else not modelled.
        def use_gazebo_model(url, *, as: nil, **)
          location = Location.of_caller
          device = Compat::Gazebo.use_model(syskit_profile, url, as: as, location: location)
          return device if device

          Syskit.app&.not_modelled("use_gazebo_model in profile #{self}", location)
          name = "#{as || url.to_s.sub(%r{\Amodel://}, '').split('/').first}_dev"
          device = Compat::Ignored.new("#{self}.#{name} (made by use_gazebo_model from the SDF file of #{url})")
          define_singleton_method(name) { device } unless respond_to?(name)
          device
        end

        # Uses +profile+ (see Definitions#use_profile): +tags+ select for its
        # tags ('localization' => X, or localization: X), +transform_names+
        # renames its definitions (->(name) { "left_\#{name}" }).
        def use_profile(profile, tags = {}, transform_names: nil, **more_tags)
          syskit_profile.use_profile(profile, tags.merge(more_tags), transform_names: transform_names,
                                                                     location: Location.of_caller)
          self
        end

        def syskit_profile
          @syskit_profile
        end

        # What every +<device>_dev+ method is (see
        # Profile#define_device_action): +__callee__+ is the action's name.
        def syskit_device_action
          @syskit_profile.find_action(__callee__)
        end
        DEVICE_ACTION = instance_method(:syskit_device_action)
        remove_method(:syskit_device_action)

        def explain_missing(name)
          actions = syskit_profile.action_names + syskit_profile.tags.keys.map { |t| "#{t}_tag" }
          ["#{self} has no action '#{name}'#{Naming.did_you_mean(name, actions)}",
           actions.empty? ? 'declare devices in its robot block' : "its actions are #{actions.join(', ')}"]
        end
      end
    end
  end
end
