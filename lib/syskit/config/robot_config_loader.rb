# frozen_string_literal: true

module Syskit
  module Config
    # The robot configurations of an app, config/robots/NAME.rb, each loaded
    # once, when a plan or a check asks for it. While one is evaluated,
    # +Syskit.conf+ is its {RobotConfig}.
    class RobotConfigLoader
      # The configuration file being evaluated, for Syskit.conf.
      attr_reader :loading

      def initialize(app)
        @app = app
        @configs = {}
      end

      # The configurations loaded so far, by robot name.
      def loaded
        @configs
      end

      # Robot names that have a configuration file, sorted.
      def names
        Dir[File.join(dir, '*.rb')].select { |p| File.file?(p) }.map { |p| File.basename(p, '.rb') }.sort
      end

      # The deployments of robot +name+, loaded from config/robots/NAME.rb.
      def [](name)
        @configs[name] ||= load(name)
      end

      private

      def dir
        File.join(@app.root, 'config', 'robots')
      end

      def load(name)
        # A name is a file of config/robots/, never a path leading elsewhere.
        raise not_a_name(name) if name.include?('/') || name.start_with?('.')

        path = File.join(dir, "#{name}.rb")
        raise missing(name, path) unless names.include?(name)

        config = RobotConfig.new(@app, name)
        @loading = config
        begin
          # Methods the file defines (helpers its blocks call) stay on this
          # object instead of becoming methods of every object.
          context = Object.new.extend(DSL::TopLevelStatements)
          robot_files_required_into(path) { evaluate(path, context) }
          run_phases(config)
          record_used_profiles(config)
        ensure
          @loading = nil
        end
        config
      end

      # The file, run with +context+ as self. Its compiled form comes from
      # the cache (ISeqCache) as a large model file's does: a 10,000-device
      # robot's file is 0.7 MB of Ruby, about 0.1 s to compile. The cache
      # keeps code, not an instance_eval of a string, so the file is
      # compiled as the body of a lambda, within +class << context+, all
      # on its first line (line numbers hold), and the lambda is run with
      # instance_exec: as with instance_eval, the methods and the
      # constants it defines stay on +context+, and a +return+ at its top
      # level ends it. A file that does not compile so is evaluated as it
      # is, for its error to be reported as written.
      def evaluate(path, context)
        body = compiled_body(path)
        return UserCode.evaluate(path, context, root: @app.root) unless body

        UserCode.guard(path: path, root: @app.root) { context.instance_exec(&body.eval.call(context)) }
      end

      # The leading comment lines stay first, so that its magic comments
      # (frozen_string_literal...) still apply; the wrapper starts the
      # first line of code.
      def compiled_body(path)
        comments, code = UserFile.read(path).match(/\A((?:[ \t]*(?:#[^\n]*)?\n)*)(.*)\z/m).captures
        ISeqCache.compile("#{comments}lambda do |context| class << context; lambda do #{code}\nend; end; end", path)
      rescue SyntaxError
        nil
      end

      # A robot file that requires another one (require_relative
      # './default') takes its deployments: Ruby's require loads a file
      # once per process, so the robot files loaded for another robot are
      # forgotten first. The file being evaluated counts as loaded: a
      # require of itself does nothing (it deployed everything twice).
      def robot_files_required_into(path)
        own = [path, File.realpath(path)].uniq
        robot_files = names.flat_map { |n| File.join(dir, "#{n}.rb").then { |f| [f, File.realpath(f)] } }
        $LOADED_FEATURES.reject! { |feature| robot_files.include?(feature) }
        $LOADED_FEATURES.push(*own)
        yield
      ensure
        own&.each { |feature| $LOADED_FEATURES.delete(feature) }
      end

      # Runs the blocks the file recorded, phase by phase. What init and
      # config blocks do is mostly Roby's business: an exception there that
      # is not a Syskit error ends the block with a warning, not an error.
      def run_phases(config)
        RobotDSL::PHASES.each do |phase, mode|
          next unless mode == :run

          config.phase_blocks(phase).each do |entry|
            phase == :requires ? run_block(entry) : run_lenient_block(entry)
          end
        end
      end

      # Robot.actions blocks are Roby's (the robot's action interface): of
      # them, only the profiles they name with use_profile are read, for
      # App#robots_loading. What else the block does is not run past the
      # first statement this reader does not know.
      def record_used_profiles(config)
        config.phase_blocks(:actions).each do |entry|
          reader = UsedProfiles.new
          begin
            reader.instance_exec(&entry.block)
          rescue StandardError, ScriptError
            nil
          end
          config.loaded_files.merge(reader.files)
        end
      end

      # What a Robot.actions block is run on (see #record_used_profiles).
      class UsedProfiles
        attr_reader :files

        def initialize
          @files = []
        end

        def use_profile(profile, *_tags, **_options)
          location = profile.respond_to?(:syskit_profile) && profile.syskit_profile&.declared_at
          @files << location.path if location
          self
        end
      end

      def run_block(entry)
        UserCode.guard(root: @app.root) { entry.block.call }
      end

      def run_lenient_block(entry)
        run_block(entry)
      rescue Syskit::Error => e
        raise unless e.is_a?(FileLoadError) && e.location

        @app.not_modelled("Robot.#{entry.phase} from this line on (#{e.message})", e.location)
      end

      def not_a_name(name)
        FileLoadError.new(
          "'#{name}' is not a robot name: robots are the files of config/robots/ (#{names.join(', ')})",
          location: Location.new(dir, nil), hint: 'give the name of a file of config/robots/, without .rb'
        )
      end

      def missing(name, path)
        FileLoadError.new(
          "no configuration for robot '#{name}'#{Naming.did_you_mean(name, names)}",
          location: Location.new(path, nil),
          hint: "create config/robots/#{name}.rb with Syskit.conf.use_deployment statements"
        )
      end
    end
  end
end
