# frozen_string_literal: true

require 'syskit/generators/name'
require 'syskit/generators/template'
require 'syskit/generators/file_writer'

module Syskit
  module Generators
    # What the generators of files in an existing app share: finding the
    # app, its name and acronyms, and writing under models/ and test/ only.
    #
    # A subclass defines #files, the relative paths and contents it writes.
    class Base
      GEM_ROOT = File.expand_path('../../..', __dir__)
      # Where generated model and test files may land, relative to the app.
      ALLOWED = %w[models test].freeze

      attr_reader :root, :app_name, :acronyms

      # The root of the app to generate into: +app_dir+ (--app) when given,
      # else the app containing +pwd+. Never the gem itself, whose models/
      # directory holds the bundled models.
      def self.find_app(app_dir, pwd: Dir.pwd)
        root = app_dir ? File.expand_path(app_dir, pwd) : Syskit::App.find_root(pwd)
        where = app_dir ? "'#{app_dir}'" : pwd
        return root if root && Syskit::App.root?(root)

        in_gem = root == GEM_ROOT || "#{File.expand_path(app_dir || pwd)}/".start_with?("#{GEM_ROOT}/")
        what = in_gem ? 'is in the syskit gem itself, not' : 'is not'
        raise GeneratorError.new(
          "#{where} #{what} in a Syskit app (#{Syskit::App::APP_HINT.split(';').first})",
          hint: 'run the command inside an app, pass --app DIR, or create an app with: syskit gen app NAME'
        )
      end

      # +force+ overwrites existing files, +dry_run+ writes nothing.
      def initialize(root, force: false, dry_run: false)
        @root = File.expand_path(root)
        settings = Syskit::App::Settings.new(@root)
        # The names of generated files come from these settings: a name
        # syskit check refuses is refused here too, never replaced.
        raise settings.problems.first if settings.problems.any?

        @app_name = settings.name
        @acronyms = settings.acronyms
        @force = force
        @dry_run = dry_run
      end

      # Writes the generated files (or only checks them on a dry run) and
      # returns what was, or would be, written.
      def run
        FileWriter.new(root, allowed: self.class::ALLOWED, force: @force, dry_run: @dry_run).write(files)
      end

      # What the user should know of the files written, after #run: none
      # unless a generator says otherwise.
      def notes
        []
      end

      # The modules a generated file of +kind+ ('Devices', 'Profiles') for
      # +name+ is nested in: AppName::Kind::Name's namespace.
      def self.modules_for(app_name, kind, name)
        Template::Modules.new([*app_name.split('::'), kind, *name.namespace])
      end

      private

      # Yields task library +name+ (loaded with its extension files), the
      # path of its .orogen file and the app, loaded as syskit check would
      # (extension files of the libraries it uses may need the app's device
      # models); the app's own problems are left to syskit check, only this
      # library's matter here.
      def with_library(name)
        app = Syskit::App.new(root)
        app.load
        path = app.orogen.spec_path(name) || raise(unknown_library(app, name))
        yield app.orogen.library(name) || load_library(app, name, path), path, app
      ensure
        app&.unload
      end

      # No .orogen file of that name: the hint also says how to start one.
      def unknown_library(app, name)
        error = app.orogen.unknown_library(name, nil, error_class: GeneratorError)
        GeneratorError.new(error.message,
                           hint: "#{error.hint}; to start a new task library: syskit gen tasklib #{name}")
      end

      # Loads a library the app does not use: an error of its .orogen file
      # stops the generator, those of its extension files are syskit
      # check's to report.
      def load_library(app, name, path)
        library = app.orogen.load_library(name, Location.new(path, 1))
        app.extension_files(name, path).each do |file|
          app.load_file(file)
        rescue Syskit::Error
          next
        end
        library
      end

      # The nested modules a model file of +kind+ (Devices, Profiles) opens.
      def modules_for(kind, name)
        self.class.modules_for(app_name, kind, name)
      end
    end
  end
end
