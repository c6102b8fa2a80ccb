# frozen_string_literal: true

require_relative '../helper'
require 'json'

module Syskit
  module SelfTest
    # What the tests of `syskit lsp` in real editors share: a copy of the
    # example app whose profile has a mistake, `syskit` on the editor's
    # PATH (this checkout's bin/syskit), the editor guide's configuration
    # for the editor, and what the diagnostic must say.
    module EditorHelper
      GUIDE = File.join(GEM_ROOT, 'doc', 'guides', 'editor.md')

      # The first executable +name+ on the PATH, nil when there is none.
      def self.find_executable(name)
        ENV['PATH'].to_s.split(File::PATH_SEPARATOR).map { |dir| File.join(dir, name) }
                   .find { |path| File.executable?(path) }
      end

      def setup
        super
        @dir = Dir.mktmpdir('syskit-editor')
      end

      def teardown
        FileUtils.rm_rf(@dir) if @dir
        super
      end

      # A copy of the example app, under its own name (which its requires
      # need); its root.
      def example_copy
        FileUtils.cp_r(File.join(GEM_ROOT, 'examples', 'awesome_robot'), @dir)
        File.join(@dir, 'awesome_robot')
      end

      # A copy of the example app whose profile names a device model that
      # does not exist; the profile's path.
      def profile_with_a_mistake
        profile = File.join(example_copy, 'models', 'profiles', 'live', 'base.rb')
        @profile_text = File.read(profile)
        File.write(profile, @profile_text.sub('Ublox::F9', 'Ublox::F8'))
        profile
      end

      # The 0-based line of the mistake.
      def mistake_line
        @profile_text.lines.index { |l| l.include?('Ublox::F9') }
      end

      MISTAKE = /uninitialized constant .*Ublox::F8/

      # The guide's code block matching +pattern+ (its first group), written
      # to +name+ in the test's directory; its path.
      def guide_configuration(pattern, name)
        snippet = File.read(GUIDE)[pattern, 1]
        assert snippet, "the editor guide has no block matching #{pattern.source[0, 60]}"
        path = File.join(@dir, name)
        File.write(path, snippet)
        path
      end

      # The environment of an editor that finds this checkout's `syskit`
      # on its PATH, with the test's directory as its HOME.
      def editor_env
        SelfTest.child_env.merge('HOME' => @dir, 'PATH' => "#{syskit_on_path}:#{ENV.fetch('PATH', '')}")
      end

      private

      def syskit_on_path
        bin = File.join(@dir, 'bin')
        FileUtils.mkdir_p(bin)
        syskit = File.join(GEM_ROOT, 'bin', 'syskit')
        File.write(File.join(bin, 'syskit'), "#!/bin/sh\nexec '#{RbConfig.ruby}' '#{syskit}' \"$@\"\n")
        File.chmod(0o755, File.join(bin, 'syskit'))
        bin
      end
    end
  end
end
