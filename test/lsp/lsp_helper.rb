# frozen_string_literal: true

require 'helper'
require 'syskit/lsp'

module Syskit
  module SelfTest
    # The language server's queries on the example app, or on a small app
    # written by the test, at a position given by the text found there.
    module LSPHelper
      EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')

      # The example app, loaded as `syskit check` loads it.
      def example_app
        @example_app ||= load_app(EXAMPLE, robots: :all, everything: true, models: true)
      end

      # The path of +relative+ in the example app.
      def example(relative)
        File.join(EXAMPLE, relative)
      end

      # The protocol's 0-based [line, character] of +needle+ in +text+
      # (its +nth+ occurrence, 0 for the first), +offset+ characters in.
      def position(text, needle, offset: 0, nth: 0)
        text.lines.each_with_index do |line, index|
          from = 0
          while (column = line.index(needle, from))
            return [index, column + offset] if nth.zero?

            nth -= 1
            from = column + 1
          end
        end
        flunk "#{needle.inspect} is not in the text"
      end

      # +query+.at(path, text, *position(text, needle, ...)), +text+ being
      # the file's unless given.
      def query_at(query, path, needle, text: File.read(path), **position)
        query.at(path, text, *position(text, needle, **position))
      end

      # The 1-based line of +needle+ in the file at +path+.
      def line_of(path, needle)
        position(File.read(path), needle).first + 1
      end

      # A small app (see my_app) whose profile file, models/profiles/base.rb,
      # fails to load: a statement of the robot block names a model that
      # does not exist. Returns the loaded app and the file's path.
      def app_with_broken_profile
        root = my_app("device(MyApp::Devices::IMU, as: 'imu')\ndevice(MyApp::Devices::Nope, as: 'nope')\n")
        app = load_app(root, problems: true, robots: [], everything: true, models: true)
        path = File.join(root, 'models/profiles/base.rb')
        assert(app.errors.any? { |e| e.location&.path == path }, 'the profile was expected to fail to load')
        [app, path]
      end
    end
  end
end
