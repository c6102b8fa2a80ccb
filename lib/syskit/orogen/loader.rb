# frozen_string_literal: true

require 'syskit/orogen/task_library'
require 'syskit/orogen/spec_loader'
require 'syskit/orogen_namespace'
require 'syskit/source_calls'

module Syskit
  module Orogen
    # The task libraries of an app: where their .orogen files are, which ones
    # are loaded, their task models and deployments.
    class Loader
      attr_reader :namespace

      def initialize(app)
        @app = app
        @libraries = {}
        # Libraries whose .orogen file is being evaluated, outermost first.
        @loading = []
        @deployments = {}
        @namespace = Namespace.new('OroGen').extend(OroGenNamespace)
        @namespace.loader = self
        @namespace.const_set(:Spec, Compat::OrogenSpec)
        # RTT's TaskContext, the root of every oroGen task model, is
        # Syskit::TaskContext (OroGen::RTT::TaskContext, as in Syskit).
        rtt = Namespace.new('OroGen', ['RTT'])
        rtt.add(['TaskContext'], Syskit::TaskContext)
        @namespace.const_set(:RTT, rtt)
        available_library_names.each { |name| @namespace.add_unloaded(name) }
      end

      # The .orogen file of +name+: the app's models/orogen/ first, then each
      # directory of SYSKIT_OROGEN_PATH, then the gem's bundled libraries.
      def spec_path(name)
        @app.orogen_search_dirs.map { |dir| File.join(dir, "#{name}.orogen") }.find { |p| File.file?(p) }
      end

      def available_library_names
        @available_library_names ||=
          @app.orogen_search_dirs.flat_map { |dir| Dir[File.join(dir, '*.orogen')].select { |p| File.file?(p) } }
              .map { |p| File.basename(p, '.orogen') }.uniq.sort
      end

      def loaded?(name)
        @libraries.key?(name)
      end

      def library(name)
        @libraries[name]
      end

      def loaded_library_names
        @libraries.keys.sort
      end

      def load_library(name, location)
        path = spec_path(name)
        raise unknown_library(name, location) unless path

        library = TaskLibrary.new(name, path)
        @libraries[name] = library
        @loading.push(name)
        begin
          SpecLoader.new(@app, library).load
          publish_deployments(library)
        rescue Exception # rubocop:disable Lint/RescueException -- undo, then re-raise as is
          @libraries.delete(name)
          raise
        ensure
          @loading.pop
        end
        @namespace.add([name], library.namespace)
        library
      end

      # The libraries being loaded from +name+ on, when +name+ is still
      # loading (its file waits for a library it loads): the chain that
      # leads back to it; nil otherwise.
      def loading_chain(name)
        index = @loading.index(name)
        index && @loading[index..]
      end

      def find_task_model(full_name)
        library(full_name.split('::').first)&.tasks&.[](full_name)
      end

      def each_task_model(&block)
        return enum_for(__method__) unless block

        @libraries.each_value { |lib| lib.tasks.each_value(&block) }
      end

      # The drivers of each device model among the task models loaded so
      # far, for what needs them while files are still being loaded (the
      # slaves of a device, bound as it is declared). Made again once a
      # library is loaded or a task model gains a service; the app settles
      # every device's driver with an index of its own once all is loaded.
      def current_driver_index
        # Asked once per device declared: compared field by field, not as
        # an array made each time.
        libraries = @libraries.size
        version = Models::Component.declarations_version
        return @driver_index if @driver_index_libraries == libraries && @driver_index_version == version

        @driver_index_libraries = libraries
        @driver_index_version = version
        @driver_index = Robot::DriverIndex.new(self)
      end

      # A deployment of +library+, which is still loading: kept with the
      # library, and in the app's table only once the whole file has loaded
      # (#publish_deployments). A file that fails is loaded again when
      # something asks for it: a deployment recorded before that failure
      # made it "already declared" at its own line.
      def register_deployment(library, deployment)
        existing = @deployments[deployment.name] || library.deployments[deployment.name]
        raise duplicate_deployment(deployment, existing) if existing

        library.deployments[deployment.name] = deployment
      end

      # The deployments of +library+, loaded, into the app's table.
      def publish_deployments(library)
        library.deployments.each_value do |deployment|
          existing = @deployments[deployment.name]
          raise duplicate_deployment(deployment, existing) if existing
        end
        @deployments.update(library.deployments)
      end

      def duplicate_deployment(deployment, existing)
        SpecError.new("deployment '#{deployment.name}' is already declared at #{existing.declared_at}",
                      location: deployment.declared_at, hint: 'deployment names are unique in an app')
      end

      def find_deployment(name)
        @deployments[name]
      end

      def deployment_names
        @deployments.keys.sort
      end

      # Task libraries on the search path whose .orogen file declares a
      # deployment called +name+, found without loading them.
      def libraries_declaring_deployment(name)
        declared_deployments.select { |_, names| names.include?(name) }.keys
      end

      # Deployment names of every task library on the search path, loaded or not.
      def all_deployment_names
        (deployment_names + declared_deployments.values.flatten).uniq.sort
      end

      # The error for a task library that is on no search directory.
      # Where the app file that would have loaded library +name+ failed.
      def failed_user_of(name)
        @app.failed_user_of_library(name)
      end

      def unknown_library(name, location, error_class: FileLoadError)
        searched = @app.orogen_search_dirs.map { |d| Location.new(d, 0).relative_path(@app.root) }
        error_class.new(
          "no task library '#{name}'#{Naming.did_you_mean(name, available_library_names)}",
          location: location,
          hint: "there is no #{name}.orogen in #{searched.join(', ')}; " \
                "create models/orogen/#{name}.orogen or add its directory to SYSKIT_OROGEN_PATH"
        )
      end

      private

      # Library name => deployment names, the deployment and
      # simple_deployment statements of the .orogen files (see SourceCalls).
      def declared_deployments
        @declared_deployments ||= available_library_names.to_h do |lib|
          calls = SourceCalls.find(UserFile.read(spec_path(lib)), %w[deployment simple_deployment])
          [lib, calls.filter_map(&:argument)]
        end
      end
    end
  end
end
