# frozen_string_literal: true

require 'syskit/checks/can_filters'
require 'syskit/checks/can_timing'

module Syskit
  # `syskit check`: loads everything in an app, generates every profile on
  # the robots that load it (every robot, when none names it), and reports all the problems found, including
  # the ones no generation error shows (overlapping CAN filters, CAN
  # frames that can miss their deadlines).
  class Check
    attr_reader :app, :problems

    def initialize(app)
      @app = app
      @problems = []
    end

    # Problems are kept in the order they are found: loading first, then
    # each profile. A profile whose own files failed to load is not
    # generated: that would only repeat the loading problems.
    #
    # With +load: false+, the app is taken as loaded already (as #load
    # loads it; `syskit lsp` keeps it loaded between checks).
    def run(load: true)
      self.class.load(app) if load
      @problems.concat(app.problems)
      @problems << opaque_typekits_note unless app.opaque_typekits.empty?
      failed_files = app.errors.filter_map { |p| p.location&.path }.uniq
      app.profiles.values.sort_by(&:name).each { |profile| check_profile(profile, failed_files) }
      @problems = @problems.uniq(&:identity)
      self
    end

    # Loads +app+ as the check needs it: every model, task library, typekit
    # and robot configuration.
    def self.load(app)
      app.load(robots: :all, everything: true, models: true)
    end

    # `check --strict`: every warning is reported as the error it becomes.
    def strict!
      @problems = problems.map do |p|
        p.is_a?(Warning) ? Error.new(p.message, location: p.location, hint: p.hint) : p
      end
      self
    end

    def errors
      problems.grep_v(Warning)
    end

    def warnings
      problems.grep(Warning)
    end

    # The robots that load the profile, as Roby loads a robot: those whose
    # configuration requires its file, directly or through other files, or
    # uses it in Robot.actions (see App::RobotFiles). A profile no robot
    # names is checked on every robot.
    def robots_of(profile)
      path = profile.declared_at&.path
      robots = path ? app.robots_loading(path) : []
      robots.empty? ? app.robot_configs.keys : robots
    end

    private

    def opaque_typekits_note
      names = app.opaque_typekits.keys.sort
      Warning.new("typekits without a description, their types taken as opaque: #{names.join(', ')}",
                  location: app.opaque_typekits.values.first,
                  hint: 'describe one in models/typekits/NAME.rb (struct, enum, opaque) to have its values checked')
    end

    def check_profile(profile, failed_files)
      @problems.concat(Checks::CanFilters.new(profile.robot).warnings)
      @problems.concat(Checks::CanTiming.new(profile).problems)
      return if profile_files(profile).intersect?(failed_files)

      robots_of(profile).each { |robot| generate(profile, robot) }
    end

    def profile_files(profile)
      ([profile.declared_at] + profile.robot.each_master_device.map(&:declared_at)).compact.map(&:path).uniq
    end

    # The devices together (they all run on the robot), then each
    # definition on its own (definitions are what the robot can run, not
    # all at once). A definition that only misses what the profile's own
    # tags stand for is checked in the profiles that use this one and
    # select them, as Syskit's is_self_contained does.
    def generate(profile, robot)
      config = app.robot_config(robot)
      generate_requirements(profile, config, profile.device_requirements)
      profile.definition_requirements.each do |definition|
        generate_requirements(profile, config, [definition], generic: true)
      end
    end

    def generate_requirements(profile, config, requirements, generic: false)
      Network::Generator.new(app, requirements, profile: profile, robot_config: config).generate
    rescue Syskit::Error => e
      return if generic && UnselectedTag.only_tags_of?(e, profile)

      e.is_a?(ErrorList) ? @problems.concat(e.errors) : @problems << e
    end
  end
end
