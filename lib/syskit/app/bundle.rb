# frozen_string_literal: true

module Syskit
  class App
    # A bundle: a directory with models/ and config/. An app is the first
    # bundle of its own list, then come the bundles it depends on, then the
    # gem's own small common_models (see BundleSearch::BUNDLED).
    #
    # A bundle's paths are relative to its +root+ (+models/orogen/x.rb+,
    # +config/orogen/x.yml+). Most bundles are all of their root: its files
    # are theirs, and the root, its models/ and its lib/ are on the load
    # path. The gem's own is only the directories +dirs+ of its root (the
    # gem's models/): the gem's lib/, test/ and templates/ are never files
    # of an app, its lib/ is never searched as a bundle's, and a user frame
    # is never found there (see Location.user_frame?).
    class Bundle
      attr_reader :name, :root

      # +dirs+: the directories of +root+ (relative) that are the bundle's,
      # nil for all of it.
      def initialize(name, root, dirs: nil)
        @name = name
        @root = root
        @dirs = dirs&.map { |d| File.join(root, d) }&.freeze
      end

      # The directories whose files are the bundle's.
      def owned_dirs
        @dirs || [root]
      end

      # Whether +path+ (absolute) is a file of the bundle.
      def owns?(path)
        owned_dirs.any? { |dir| path.start_with?("#{dir}/") }
      end

      # The directories `require` searches first: 'models/devices/x' from the
      # root, 'devices/x' from models/, and the Ruby code of lib/ that its
      # models require, as in Rock; only the bundle's own for a bundle that
      # is not all of its root.
      def load_path
        return owned_dirs unless @dirs.nil?

        [root, File.join(root, 'models'), File.join(root, 'lib')]
      end

      # The directory searched last, from which 'NAME/models/x' (a bundle
      # requiring another's files) is found: the one holding the bundle;
      # nil for a bundle that is not all of its root (see #named_file).
      def parent_dir
        File.dirname(root) if @dirs.nil?
      end

      # The bundle's file at +relative+ ('models/devices/x.rb',
      # 'config/orogen/lib::Task.yml'), nil when it has none.
      def file(relative)
        path = File.expand_path(relative, root)
        path if owns?(path) && File.file?(path)
      end

      # The first part of the names its files are required under from
      # other bundles ('common_models/models/devices/bus/can'): the name of
      # its directory, which the load path finds it by (see #parent_dir),
      # or its own name for a bundle that is not all of its root.
      def require_name
        @dirs.nil? ? File.basename(root) : name
      end

      # The bundle's file that `require +name+` (with .rb) means when the
      # bundle's parent directory is not on the load path: 'NAME/models/x.rb'
      # and 'models/x.rb' of a bundle that is not all of its root; nil
      # otherwise.
      def named_file(name)
        file(name.delete_prefix("#{require_name}/")) unless @dirs.nil?
      end

      def to_s
        "bundle #{name} (#{owned_dirs.join(', ')})"
      end
    end
  end
end
