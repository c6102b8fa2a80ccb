# frozen_string_literal: true

require 'thor'
require 'syskit/errors'

module Syskit
  class CLI < Thor
    # What the command classes (syskit, syskit gen, syskit bus) share:
    # finding the app and the profile, and printing errors as
    # `file:line: message` then `  hint: ...`, with Ruby's backtrace only
    # under --trace, and exit status 1.
    module Support
      # Thor runs every command through here: what the command needs is
      # loaded first (see Help#libraries), so that `syskit help` and each
      # command load only what they use. An unknown command (Thor's
      # DynamicCommand) needs nothing to say so.
      def invoke_command(command, *args)
        unless command.name == 'help' || command.is_a?(Thor::DynamicCommand)
          Support.without_gc { self.class.libraries(command.name).each { |path| Support.require_once(path) } }
        end
        super
      end

      # Requires +path+ the first time only. Ruby's require of a file it has
      # loaded is not free once an app has marked its own files loaded: it
      # indexes its loaded features again, resolving the real path of each
      # (thousands of system calls for each command run in one process, as
      # tests run them).
      # Runs the block with the garbage collector off, then on again: for
      # loading the gem's code and the app's models, which live as long as
      # the process, so that collecting while they load frees next to
      # nothing (5 of the 8 full collections of `syskit plan` of 10,000
      # devices, 0.2 s; see doc/performance.md).
      def self.without_gc
        was_off = GC.disable
        yield
      ensure
        GC.enable unless was_off
      end

      def self.require_once(path)
        (@required ||= {})[path] ||= require(path) || true
      end

      private

      # What a command loads as it goes, once (see Support.require_once).
      def require_once(path)
        Support.require_once(path)
      end

      # Runs the block; a Syskit error is printed for the user (paths
      # relative to what +root+ returns), any other exception is reported as
      # a bug of syskit.
      def reporting_errors(root = -> {})
        yield
      rescue Interrupt
        # Ctrl-C: the user knows why it stopped.
        exit 130
      rescue Errno::EPIPE
        # The reader went away (syskit check | head): nothing more to say.
        exit 0
      rescue Syskit::Error => e
        report_error(e, root.call)
      rescue StandardError, ScriptError => e
        internal = Error.new("internal error: #{e.class}: #{e.message}",
                             hint: 'this is a bug in syskit; run again with --trace and report the backtrace')
        internal.set_backtrace(e.backtrace)
        report_error(internal, root.call)
      end

      # Runs the block with the app of --app (loaded unless load: false),
      # unloaded afterwards.
      def with_app(load: true, robots: ['default'])
        app = nil
        reporting_errors(-> { app&.root }) do
          app = App.new(app_root)
          begin
            load ? Support.without_gc { app.load!(robots: robots) } : app.activate
            yield app
          ensure
            app.unload
          end
        end
      end

      # --app (which must be an app), else the app containing the current
      # directory. Outside an app every command says so (as gen does)
      # rather than quietly working on another app.
      def app_root
        return App.check_root(options[:app]) if options[:app]

        found = App.find_root(Dir.pwd)
        return found if found

        raise Error.new("#{Dir.pwd} is not in a Syskit app", hint: "pass --app DIR, or cd into an app; #{App::APP_HINT}")
      end

      # The profile called +name+: its full name or the end of it, in
      # constant form (Live::Base) or in the path form of `gen profile`
      # (live/base). Without +name+, the app's first profile, unless it has
      # no device while others do (the error's example runs +command+).
      def find_profile(app, name, command:)
        profiles = app.profiles.values.sort_by(&:name)
        return default_profile(app, profiles, command) if name.nil?

        matches = profiles_ending_with(name, profiles)
        return matches.first if matches.size == 1
        raise no_profile(name, profiles) if matches.empty?

        raise UnknownName.new("'#{name}' names several profiles: #{matches.map(&:name).join(', ')}",
                              hint: "type one of #{matches.map { |p| shortest_name(p, profiles) }.join(', ')}")
      end

      # The profiles whose name ends with +name+; only the one +name+ is
      # the path of under the app's Profiles when there is one (Base is
      # Profiles::Base rather than Profiles::Live::Base, as it is for Ruby
      # code inside Profiles).
      def profiles_ending_with(name, profiles)
        wanted = profile_segments(name)
        matches = profiles.select { |p| profile_segments(p.name).last(wanted.size) == wanted }
        exact = matches.select { |p| profile_path(p.name) == wanted.join('/') }
        exact.size == 1 ? exact : matches
      end

      def no_profile(name, profiles)
        names = profiles.map(&:name)
        spelled = name.include?('/') ? profiles.map { |p| profile_path(p.name) } : names
        UnknownName.new("no profile named '#{name}'#{Naming.did_you_mean(name, spelled)}",
                        hint: "profiles: #{names.join(', ')}")
      end

      # The shortest end of +profile+'s name that names it alone among
      # +profiles+ (Live::Base when Sim::Base exists).
      def shortest_name(profile, profiles)
        constants = profile.name.split('::')
        others = profiles.reject { |p| p.equal?(profile) }.map { |p| profile_segments(p.name) }
        size = (1..constants.size).find do |n|
          ending = profile_segments(profile.name).last(n)
          others.none? { |o| o.last(n) == ending }
        end
        constants.last(size || constants.size).join('::')
      end

      # 'Live::Base', 'live/base' and 'Profiles::Live::Base' -> [..., 'live', 'base']
      def profile_segments(name)
        name.to_s.split(%r{::|/}).reject(&:empty?).map { |s| Naming.underscore(s) }
      end

      # AwesomeRobot::Profiles::Live::Base -> 'live/base', as gen profile takes it
      def profile_path(name)
        segments = profile_segments(name)
        after = segments.index('profiles')
        (after ? segments.drop(after + 1) : segments).join('/')
      end

      def default_profile(app, profiles, command)
        if profiles.empty?
          raise UnknownName.new("#{app} has no profile",
                                hint: 'declare one in models/profiles/ (syskit gen profile NAME)')
        end

        first = profiles.first
        return first unless first.action_names.empty?

        with_devices = profiles.reject { |p| p.action_names.empty? }
        return first if with_devices.empty?

        raise UnknownName.new("#{first.name}, the app's first profile, has no device",
                              hint: "name the profile to plan: #{with_devices.map(&:name).join(', ')} " \
                                    "(e.g. syskit #{command} #{with_devices.first.name})")
      end

      def report_error(error, root)
        warn Style.for($stderr).report(error, root)
        warn (error.backtrace || []).map { |l| "    #{l}" }.join("\n") if trace?
        exit(1)
      end

      # --trace is also the main command's option: Thor gives it to `syskit`
      # rather than to `syskit gen`/`syskit bus`, wherever it is written.
      def trace?
        options[:trace] || (respond_to?(:parent_options) && (parent_options || {})['trace'])
      end
    end
  end
end
