# frozen_string_literal: true

module Syskit
  module LSP
    # One app, loaded as `syskit check` loads it, kept loaded between
    # requests, and checked again when a file the editor has open changes,
    # as far as the change needs (see #kind_of):
    #
    # - a configuration file (config/orogen/*.yml): that file is read and
    #   checked again, and the profiles generated again, on the models
    #   already loaded;
    # - a Ruby file of the app (or of a bundle it uses), an .orogen spec or
    #   the app's settings: the
    #   app is unloaded and loaded again (a file's constants and the
    #   models they made cannot be taken back one by one);
    # - anything else (a test, a README): nothing.
    #
    # Files open in the editor are read from its buffers, saved or not (see
    # UserFile.with_buffers).
    class Session
      attr_reader :root, :app, :problems

      # How long the last check took, in seconds, and how far it went
      # (:load, :conf).
      attr_reader :last_check

      # The number of checks so far: what was made from the app (the query
      # capabilities' catalogs) is made again once it changes.
      attr_reader :generation

      def initialize(root, log: $stderr)
        @root = root
        @buffers = {}
        @checked = {}
        @problems = []
        @log = log
        @generation = 0
      end

      # The texts of the files open in the editor, by path.
      def buffers
        @buffers.dup
      end

      # The file at +path+ is open with +text+ (or changed to it); checks
      # the app again as far as that needs. Returns whether it did.
      def update(path, text)
        @buffers[path] = text
        refresh(path)
      end

      # The file at +path+ is no longer open: it is read from disk again.
      def close(path)
        @buffers.delete(path)
        refresh(path)
      end

      # Loads and checks the app unless it is loaded (a first request, or
      # another app was loaded meanwhile).
      def ensure_loaded
        reload unless app_active?
        self
      end

      # Runs the block with the app active and the editor's buffers read
      # instead of the files (the queries may read files).
      def with_app
        ensure_loaded
        UserFile.with_buffers(@buffers) { yield app }
      end

      # Unloads the app, so that another can be loaded.
      def unload
        @app&.unload
        @app = nil
      end

      # :conf, :load or nil: what a change of +path+ needs (see the class).
      def kind_of(path)
        base = roots.find { |dir| path.start_with?("#{dir}/") } or return
        relative = path.delete_prefix("#{base}/")
        return :conf if relative.match?(%r{\Aconfig/orogen/[^/]+\.yml\z})
        return :load if relative.end_with?('.orogen')
        return :load if relative.end_with?('.rb') && relative.start_with?('models/', 'config/', 'lib/')

        :load if App::ROOT_FILES.include?(relative) || relative.match?(%r{\Aconfig/[^/]+\.yml\z})
      end

      # The directories of the files the app reads: its own and, once it
      # was loaded, its bundles' (a file of common_models opened from a
      # definition is served by the app that uses it, and its changes
      # checked on it).
      def roots
        @roots || [root]
      end

      private

      def refresh(path)
        kind = kind_of(path)
        return reload unless app_active?
        return false if kind.nil? || UserFile.with_buffers(@buffers) { current_text(path) } == checked_text(path)

        kind == :conf ? recheck_conf(path) : reload
      end

      def app_active?
        @app && Syskit.app.equal?(@app)
      end

      # The app unloaded (the other one too, if another is loaded) and
      # loaded again from scratch, then checked.
      def reload
        Syskit.app&.unload
        @app = nil
        checking(:load) do
          @app = App.new(root)
          @roots = [root, *@app.bundle_roots].uniq
          Check.load(@app)
          @kept = @app.problems.size
          Check.new(@app).run(load: false).problems
        end
      end

      # The configuration file +path+ read and checked again, and the
      # profiles generated again, on the models loaded.
      def recheck_conf(path)
        checking(:conf) do
          @kept = app.reread_conf_file(path, kept: @kept)
          Check.new(app).run(load: false).problems
        end
      end

      # Runs a check (the block returns its problems) on the buffers,
      # recording what was checked and how long it took. A bug met on the
      # way is a problem of the app rather than the end of the server.
      def checking(how)
        started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        @generation += 1
        @problems = UserFile.with_buffers(@buffers) do
          @checked = @buffers.keys.to_h { |path| [path, current_text(path)] }
          yield
        end
        true
      rescue Syskit::Error => e
        @problems = e.is_a?(ErrorList) ? e.errors : [e]
        true
      rescue StandardError, ScriptError, SystemStackError => e
        @problems = [internal_error(e)]
        true
      ensure
        @last_check = [Process.clock_gettime(Process::CLOCK_MONOTONIC) - started, how]
      end

      # The text of +path+ the last check read: its buffer's then, else
      # the file's.
      def checked_text(path)
        @checked.fetch(path) { current_text(path) }
      end

      def current_text(path)
        UserFile.read(path)
      rescue Syskit::Error
        nil
      end

      def internal_error(exception)
        @log.puts "syskit lsp: internal error while checking #{root}: #{exception.class}: #{exception.message}"
        @log.puts((exception.backtrace || []).map { |l| "    #{l}" })
        Error.new("internal error of syskit while checking the app: #{exception.class}: #{exception.message}",
                  hint: 'this is a bug in syskit; the server log (stderr) has the backtrace, please report it')
      end
    end
  end
end
