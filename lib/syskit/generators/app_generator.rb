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

      attr_reader :root, :app_name

      # +dir+: the app's directory, relative to +pwd+; its basename, camelized,
      # is the app's name.
      def initialize(dir, pwd: Dir.pwd, force: false, dry_run: false)
        dir = dir.to_s.chomp('/')
        check_dir(dir)
        @root = File.expand_path(dir, pwd)
        @app_name = Name.parse(File.basename(dir), what: 'app', acronyms: ACRONYMS,
                                                   examples: 'e.g. awesome_robot').to_s
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

      # Relative path => content of the files to write.
      def files
        locals = { app_name: app_name, dir_name: File.basename(root), acronyms: ACRONYMS, version: Syskit::VERSION }
        files = {
          'README.md' => Template.render('app_readme', **locals),
          'Gemfile' => Template.render('app_gemfile', **locals),
          'Rakefile' => Template.render('app_rakefile', **locals),
          'config/syskit.yml' => Template.render('app_syskit_yml', **locals),
          'config/robots/default.rb' => Template.render('app_robot', **locals)
        }
        EMPTY_DIRS.each { |d| files["#{d}/.gitkeep"] = '' }
        files.merge(ProfileGenerator.files(app_name, Name.new(['Base']))).sort.to_h
      end

      # How to run the new app's tests: rake finds an installed syskit;
      # from a checkout, Bundler takes it from SYSKIT_PATH (see the Gemfile).
      def next_step
        dir = Shellwords.escape(root.delete_prefix("#{Dir.pwd}/"))
        return "cd #{dir} && rake test" unless checkout?

        "cd #{dir} && SYSKIT_PATH=#{Shellwords.escape(GEM_ROOT)} bundle exec rake test"
      end

      private

      def check_dir(dir)
        return unless dir.empty? || dir.start_with?('/', '~') || dir.split('/').include?('..')

        raise GeneratorError.new("'#{dir}' is not a directory name relative to the current directory",
                                 hint: 'run syskit gen app from the directory the app goes in, ' \
                                       'e.g. syskit gen app awesome_robot')
      end

      # Installed gems do not ship their gemspec, checkouts do.
      def checkout?
        File.file?(File.join(GEM_ROOT, 'syskit.gemspec')) &&
          Gem.path.none? { |dir| GEM_ROOT.start_with?(File.join(File.expand_path(dir), 'gems', '')) }
      end
    end
  end
end
