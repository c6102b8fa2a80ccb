# frozen_string_literal: true

require 'thor'
require 'syskit'
require 'syskit/check'
require 'syskit/render/text'
require 'syskit/render/json'
require 'syskit/render/dot'

module Syskit
  # `syskit`: thin Thor commands that parse options, call one function of the
  # library and print its result.
  class CLI < Thor
    GEM_ROOT = File.expand_path('../..', __dir__)
    EXAMPLE_APP = File.join(GEM_ROOT, 'examples', 'awesome_robot')
    RENDERERS = { 'text' => Render::Text, 'json' => Render::JSON, 'dot' => Render::Dot }.freeze

    def self.exit_on_failure?
      true
    end

    class_option :trace, type: :boolean, default: false, desc: 'show the backtrace of errors'

    desc 'version', 'print the version'
    def version
      puts "syskit #{Syskit::VERSION}"
    end

    desc 'plan [PROFILE] [ACTION...]', 'print the connection plan of a profile'
    long_desc <<~TEXT
      Generates the network of PROFILE (all its devices, or the given actions,
      e.g. gps_dev) on a robot and prints the plan: tasks, deployments,
      configuration, ports, connections and the configure/start order.

      Without --app, the app containing the current directory, else the
      bundled example app. Without PROFILE, the app's first profile.

      Example: syskit plan Live::Base temperature_sensor_dev --format json
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    method_option :robot, type: :string, default: 'default', desc: 'the robot configuration (config/robots/NAME.rb)'
    method_option :format, type: :string, default: 'text', enum: RENDERERS.keys, desc: 'output format'
    def plan(profile_name = nil, *actions)
      with_app(robots: [options[:robot]]) do |app|
        profile = find_profile(app, profile_name)
        result = Network::Generator.plan_profile(app, profile, actions: actions, robot: options[:robot])
        $stdout.write(RENDERERS.fetch(options[:format]).render(result.plan))
      end
    end

    desc 'check', 'load an app, generate every profile on every robot, report every problem'
    long_desc <<~TEXT
      Reports all the problems found (not only the first), grouped by file,
      and exits with status 1 if there is any error. Overlapping CAN filters
      are warnings; --strict makes them errors.

      Example: syskit check --app ~/dev/awesome_robot --format json
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    method_option :strict, type: :boolean, default: false, desc: 'treat warnings as errors'
    method_option :format, type: :string, default: 'text', enum: %w[text json], desc: 'output format'
    def check
      with_app(load: false) do |app|
        report = Check.new(app).run
        failed = report.errors.any? || (options[:strict] && report.warnings.any?)
        print_check(app, report)
        exit(1) if failed
      end
    end

    desc 'test [FILES...]', "run an app's tests (every test/**/test_*.rb by default)"
    long_desc <<~TEXT
      Runs the app's minitest files with the gem's test harness
      (require 'syskit/test'), in the app's directory. Exits with a non-zero
      status when a test fails.

      Example: syskit test test/profiles/live/test_base.rb
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    def test(*files)
      root = app_root
      files = files.map { |f| File.expand_path(f) }
      files = Dir[File.join(root, 'test', '**', 'test_*.rb')].sort if files.empty?
      loader = 'ARGV.each { |f| require f }'
      ok = system({ 'SYSKIT_APP' => root }, RbConfig.ruby, '-I', File.expand_path('..', __dir__),
                  '-e', loader, *files, chdir: root)
      exit($?.exitstatus || 1) unless ok # rubocop:disable Style/SpecialGlobalVars
    end

    private

    # Runs the block with the app of --app (loaded unless load: false),
    # printing Syskit errors as file:line: message + hint.
    def with_app(load: true, robots: ['default'])
      app = App.new(app_root)
      begin
        load ? app.load!(robots: robots) : app.activate
        yield app
      ensure
        app.unload
      end
    rescue Syskit::Error => e
      report_error(e, app&.root)
    rescue StandardError, ScriptError => e
      # A bug of syskit itself: say so, without a backtrace unless asked.
      report_error(Error.new("internal error: #{e.class}: #{e.message}",
                             hint: 'this is a bug in syskit; run again with --trace and report the backtrace')
                        .tap { |err| err.set_backtrace(e.backtrace) }, app&.root)
    end

    def app_root
      return File.expand_path(options[:app]) if options[:app]

      found = App.find_root(Dir.pwd)
      found && found != GEM_ROOT ? found : EXAMPLE_APP
    end

    def find_profile(app, name)
      profiles = app.profiles.values.sort_by(&:name)
      if name.nil?
        return profiles.first if profiles.any?

        raise UnknownName.new("#{app} has no profile", hint: 'declare one in models/profiles/ (syskit gen profile NAME)')
      end

      matches = profiles.select { |p| p.name == name || p.name.end_with?("::#{name}") }
      return matches.first if matches.size == 1

      names = profiles.map(&:name)
      raise UnknownName.new("no profile named '#{name}'#{Naming.did_you_mean(name, names)}", hint: "profiles: #{names.join(', ')}") if matches.empty?

      raise UnknownName.new("'#{name}' names several profiles: #{matches.map(&:name).join(', ')}",
                            hint: 'give more of the name')
    end

    def report_error(error, root)
      warn error.report(root)
      warn (error.backtrace || []).map { |l| "    #{l}" }.join("\n") if options[:trace]
      exit(1)
    end

    def print_check(app, report)
      if options[:format] == 'json'
        require 'json'
        puts ::JSON.pretty_generate('app' => app.name, 'errors' => report.errors.size,
                                    'warnings' => report.warnings.size,
                                    'problems' => report.problems.map { |p| p.to_h(app.root) })
        return
      end

      # Files in the order their first problem was found, which puts the
      # cause before what follows from it; lines in order within a file.
      groups = report.problems.group_by { |p| p.location&.relative_path(app.root).to_s }
      groups.each_with_index do |(_file, problems), i|
        puts if i.positive?
        problems.sort_by { |p| p.location&.lineno.to_i }.each do |p|
          puts p.report(app.root)
          puts (p.backtrace || []).map { |l| "    #{l}" } if options[:trace]
        end
      end
      puts "#{app.name}: #{report.errors.size} error(s), #{report.warnings.size} warning(s)"
    end
  end
end
require 'syskit/cli/bus'
require 'syskit/cli/gen'
