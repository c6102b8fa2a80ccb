# frozen_string_literal: true

require 'syskit/generators/base'
require 'syskit/generators/profile_generator'
require 'shellwords'
require 'syskit/version'

module Syskit
  module Generators
    # `syskit gen app awesome_robot`: a new app directory with the layout of
    # SPEC section 1, a Base profile and its test, ready for `rake test`.
    class AppGenerator
      GEM_ROOT = Base::GEM_ROOT
      # Acronyms most robots need; the app's config lists them, to edit.
      ACRONYMS = %w[GPS CAN IMU].freeze
      # Directories that start empty, kept by git through a .gitkeep.
      EMPTY_DIRS = %w[models/devices models/services models/compositions models/orogen models/typekits
                      config/orogen].freeze

      # +dir+ is the directory as given, for messages; +root+ its full path.
      attr_reader :dir, :root, :app_name

      # +dir+: the app's directory, relative to +pwd+ or absolute; its
      # basename, camelized, is the app's name (see App::Settings.default_name).
      def initialize(dir, pwd: Dir.pwd, force: false, dry_run: false)
        dir = dir.to_s.chomp('/')
        check_dir(dir)
        @dir = dir
        @root = File.expand_path(dir, pwd)
        @app_name = Name.parse(App::Settings.directory_words(File.basename(@root)),
                               what: 'app', acronyms: ACRONYMS, examples: 'e.g. awesome_robot or my-robot').to_s
        check_name_is_free(dir)
        @force = force
        @dry_run = dry_run
      end

      # Writes the app's files (or only checks them on a dry run) and returns
      # what was, or would be, written.
      def run
        FileWriter.new(root, allowed: ['.'], force: @force, dry_run: @dry_run).write(files)
      end

      # An app named Kernel or Conf would define its modules inside them
      # (see App::Settings.taken_by).
      def check_name_is_free(dir)
        taken = App::Settings.taken_by(app_name)
        return unless taken

        raise GeneratorError.new("the app name '#{app_name}' (from '#{File.basename(dir)}') is taken: #{app_name} is " \
                                 "#{taken}; the app's modules would be defined inside it",
                                 hint: "choose another directory name, e.g. syskit gen app #{File.basename(dir)}_robot")
      end

      # The app's next step is said instead (see #next_step).
      def notes
        []
      end

      # Relative path => content of the files to write.
      def files
        locals = { app_name: app_name, dir_name: File.basename(root), acronyms: ACRONYMS, version: Syskit::VERSION,
                   checkout: (GEM_ROOT if checkout?) }
        files = {
          '.gitignore' => Template.render('app_gitignore', **locals),
          'README.md' => Template.render('app_readme', **locals),
          'Gemfile' => Template.render('app_gemfile', **locals),
          'Rakefile' => Template.render('app_rakefile', **locals),
          'config/syskit.yml' => Template.render('app_syskit_yml', **locals),
          'config/robots/default.rb' => Template.render('app_robot', **locals)
        }
        EMPTY_DIRS.each { |d| files["#{d}/.gitkeep"] = '' }
        files.merge(ProfileGenerator.files(app_name, Name.new(['Base']))).sort.to_h
      end

      # How to run the new app's tests. The Rakefile sets Bundler up, and
      # the Gemfile names this syskit: the installed gem, or the checkout
      # the app was made from, by its path.
      def next_step
        "cd #{Shellwords.escape(dir)} && rake test"
      end

      private

      def check_dir(dir)
        return unless dir.empty?

        raise GeneratorError.new('an app needs a directory name',
                                 hint: 'give the directory to create, e.g. syskit gen app awesome_robot')
      end

      # Installed gems do not ship their gemspec, checkouts do.
      def checkout?
        File.file?(File.join(GEM_ROOT, 'syskit.gemspec')) &&
          Gem.path.none? { |dir| GEM_ROOT.start_with?(File.join(File.expand_path(dir), 'gems', '')) }
      end
    end
  end
end
