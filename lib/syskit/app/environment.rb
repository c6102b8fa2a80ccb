# frozen_string_literal: true

module Syskit
  class App
    # What an active app installs in the Ruby process, and takes back on
    # unload: the top-level constants its files write (+OroGen+, +Types+,
    # and the Rock names listed in {#constants}), its load path, and the
    # files and constants its code defined.
    #
    # Only one app is active at a time (DSL statements act on Syskit.app).
    class Environment
      def initialize(app)
        @app = app
        @active = false
      end

      def active?
        @active
      end

      # The namespaces an active app installs, besides Compat.constants.
      INSTALLED = %i[OroGen Types].freeze

      # The top-level constants an active app installs, by name. Each is
      # replaced while the app is active and removed on {#deactivate}.
      def constants
        INSTALLED.zip([@app.orogen.namespace, @app.types.namespace]).to_h.merge(Compat.constants)
      end

      # Directories on $LOAD_PATH while the app is active: 'models/devices/x'
      # and 'devices/x' resolve from the app and its bundles (searched
      # first, see Bundle#load_path); 'common_models/models/x' (bundles
      # requiring each other's files, and the seed's NMEA2000 example)
      # through their parents, searched last (the gem's own bundle has
      # none: App::Files#required_file finds its files by name).
      def load_path
        first = @app.bundles.flat_map(&:load_path)
        [first, @app.bundles.filter_map(&:parent_dir).uniq - first]
      end

      # The directories of #load_path while the app is active, in the order
      # Ruby's require searches them.
      def require_dirs
        @active ? @first + @last : []
      end

      def activate
        raise Error, "#{Syskit.app} is still loaded, unload it first" if Syskit.app && !Syskit.app.equal?(@app)
        return if @active

        @constants_before = Object.constants
        @first, @last = load_path
        $LOAD_PATH.unshift(*@first)
        $LOAD_PATH.push(*@last)
        Syskit.app = @app
        @active = true
      end

      # Installs the constants; called once the objects they name exist.
      def install_constants
        constants.each do |name, value|
          Object.send(:remove_const, name) if Object.const_defined?(name, false)
          Object.const_set(name, value)
        end
      end

      # Removes everything the app defined: constants, loaded files, load path.
      def deactivate
        return unless @active

        (Object.constants - @constants_before).each do |const|
          Object.send(:remove_const, const) if owned_constant?(const)
        end
        constants.each do |name, value|
          Object.send(:remove_const, name) if Object.const_defined?(name, false)
          value.forget if value.is_a?(Namespace)
        end
        $LOADED_FEATURES.reject! { |f| owned_file?(f) }
        (@first + @last).each { |dir| $LOAD_PATH.delete(dir) }
        Models::DataServiceModel.forget_submodels_of_roots
        Syskit.app = nil
        @active = false
      end

      # The top-level modules the app's files defined (AwesomeRobot,
      # CommonModels...), sorted by name: where its models are.
      def defined_modules
        return [] unless @active

        names = (Object.constants - @constants_before - constants.keys).select { |c| owned_constant?(c) }
        names.sort.map { |c| Object.const_get(c) }.grep(Module)
      end

      # Whether +path+ belongs to the app or one of its bundles (and is
      # forgotten on unload).
      def owned_file?(path)
        @app.bundles.any? { |bundle| bundle.owns?(path) }
      end

      private

      # Constants the app's files defined, or the gem on their behalf (the
      # modules a file is evaluated in).
      def owned_constant?(const)
        path, = Object.const_source_location(const)
        path.nil? || owned_file?(path) || path.start_with?(Location::GEM_LIB)
      end
    end
  end
end
