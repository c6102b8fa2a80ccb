# frozen_string_literal: true

require 'set'

module Syskit
  class App
    # Which robot loads which file, as Roby loads a robot: the files its
    # configuration requires (in Robot.requires, or at its top), the files
    # those require in turn, and the profiles its Robot.actions block
    # uses. Every require of a file of the app or of its bundles is
    # recorded, whether the file was loaded then or before, so that what a
    # robot loads is known whatever order the files were loaded in.
    class RobotFiles
      def initialize
        @edges = Hash.new { |hash, from| hash[from] = Set.new }
      end

      # Records that the code at +from+ (a file) requires the file +to+.
      def required(from, to)
        @edges[key(from)] << key(to)
      end

      # Whether +path+ is one of +roots+ or required by one of them,
      # directly or not.
      def reaches?(roots, path)
        target = key(path)
        seen = Set.new
        pending = roots.map { |root| key(root) }
        until pending.empty?
          file = pending.pop
          return true if file == target
          next unless seen.add?(file)

          pending.concat(@edges.fetch(file, Set.new).to_a)
        end
        false
      end

      private

      def key(path)
        File.realpath(path)
      rescue SystemCallError
        File.expand_path(path)
      end
    end
  end
end
