# frozen_string_literal: true

require 'syskit/source_calls'

module Syskit
  class App
    # The +Roby.app.register_app 'path'+ calls of a robot configuration,
    # found by Ruby's parser before the file runs (it runs after the models
    # the bundles it names make loadable; see SourceCalls).
    module RegisteredApps
      module_function

      # [path, Location] of each call whose path is written as a string,
      # and a warning for each call whose path is computed.
      def of(path)
        calls = SourceCalls.find(UserFile.read(path), %w[register_app])
        written, computed = calls.partition(&:argument)
        [written.map { |call| [call.argument, Location.new(path, call.line)] },
         computed.map { |call| computed_path(Location.new(path, call.line)) }]
      end

      def computed_path(location)
        Warning.new(
          'Roby.app.register_app with a path computed in Ruby: syskit reads bundles before robot ' \
          'configurations run, so this bundle is not searched',
          location: location,
          hint: "write the path as a string relative to the app (register_app '../other_bundle'), or name the " \
                'bundle in config/syskit.yml: bundles: [other_bundle]'
        )
      end
    end
  end
end
