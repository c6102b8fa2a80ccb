# frozen_string_literal: true

require 'tmpdir'

module Syskit
  module Test
    # The app of Syskit's own tests: they make every model they use, so it
    # is an empty one (the gem's bundled models only), in a directory of
    # its own, made once per process and removed at exit.
    module SelfApp
      NAME = 'SyskitSelfTest'

      def self.app
        @app ||= begin
          root = Dir.mktmpdir('syskit-self')
          at_exit { FileUtils.rm_rf(root) }
          app = App.new(root, name: NAME)
          app.load(robots: [], models: false)
          Syskit.app = app
          Test.app = app
          app
        end
      end
    end
  end
end
