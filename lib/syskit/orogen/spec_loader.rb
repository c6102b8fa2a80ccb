# frozen_string_literal: true

require 'syskit/orogen/spec_dsl'

module Syskit
  module Orogen
    # Reads one .orogen file (oroGen's own Ruby syntax) into a TaskLibrary:
    # a task model class per task_context and a DeploymentSpec per deployment.
    class SpecLoader
      attr_reader :library

      def initialize(app, library)
        @app = app
        @library = library
        @opaque_ok = false
      end

      def load
        UserCode.evaluate(library.path, ProjectDSL.new(self), root: @app.root, error_class: SpecError)
        library
      end

      def check_project_name(name, location)
        return if name == library.name

        raise SpecError.new("#{File.basename(library.path)} declares the project name '#{name}'",
                            location: location, hint: "the file of task library '#{name}' must be named #{name}.orogen")
      end

      def define_task(name, parent_name, location, &block)
        full_name = "#{library.name}::#{name}"
        if library.tasks.key?(full_name)
          raise SpecError.new("task_context '#{name}' is declared twice",
                              location: location, hint: 'give each task context its own name')
        end

        spec = TaskSpec.new(full_name, library, location: location)
        @parent_model = Syskit::TaskContext
        subclass(spec, parent_name, location) if parent_name
        TaskContextDSL.new(self, spec).instance_eval(&block) if block
        spec.extended_state_support(resolve_type('/int32_t', location))
        spec.finalize
        library.add_task(@parent_model.new_model(spec))
      end

      # Makes +spec+ a subclass of the task model called +parent_name+.
      def subclass(spec, parent_name, location)
        @parent_model = find_task_model(parent_name, location)
        spec.superclass = @parent_model.spec
      end

      def define_deployment(name, location, &block)
        deployment = DeploymentSpec.new(name, location)
        DeploymentDSL.new(self, deployment).instance_eval(&block) if block
        @app.orogen.register_deployment(library, deployment)
      end

      # +import_types_from+: a typekit, or a C/C++ header. A header may
      # declare types of any namespace: in a file that imports one, a type
      # no typekit describes is accepted as opaque.
      def import_types(name, location)
        @opaque_ok = true if @app.import_types(name, location: location) == :header
      end

      # The project declares a typekit of its own (a typekit block): its
      # types (/NAME/) are opaque.
      def own_typekit
        @app.types.opaque_typekit(library.name)
      end

      def using_task_library(name, location)
        @app.using_task_library(name, location: location)
      end

      def resolve_type(name, location)
        @app.types.resolve(name, location: location, opaque_ok: @opaque_ok)
      end

      # A task model by full name, or by name relative to this library.
      def find_task_model(name, location)
        found = library.find_task(name) || @app.orogen.find_task_model(name) || load_library_of(name, location)
        return found if found

        lib_name = name.split('::').first
        if name.include?('::') && !@app.orogen.loaded?(lib_name) && lib_name != library.name
          raise @app.orogen.unknown_library(lib_name, location, error_class: SpecError)
        end
        raise loading_cycle(name, lib_name, location) if lib_name != library.name && @app.orogen.loading_chain(lib_name)

        raise unknown_task_model(name, location)
      end

      def unknown_task_model(name, location)
        known = known_task_names
        hint = if known.empty? then 'no task model is loaded here: load its library first'
               else "the task models known here are #{known.join(', ')}"
               end
        SpecError.new("unknown task model '#{name}'#{Naming.did_you_mean(name, known)}", location: location, hint: hint)
      end

      # +name+ is in a library that is still loading: it loads, directly
      # or not, the library being read, before declaring its own tasks.
      def loading_cycle(name, lib_name, location)
        chain = [*@app.orogen.loading_chain(lib_name), lib_name]
        SpecError.new(
          "task model '#{name}' does not exist yet: task library '#{lib_name}' is still loading, waiting for " \
          "'#{library.name}', which it loads; these libraries load each other in a cycle (#{chain.join(' -> ')})",
          location: location,
          hint: "a library's dependencies load before it: remove the using_task_library (or the subclasses) " \
                "of one of #{chain.uniq.map { |l| "#{l}.orogen" }.join(', ')} that closes the cycle"
        )
      end

      # A full name loads its library, as oroGen does ('logger::Logger').
      def load_library_of(name, location)
        lib_name = name.split('::').first
        return unless name.include?('::') && lib_name != library.name &&
                      @app.orogen.available_library_names.include?(lib_name)

        @app.using_task_library(lib_name, location: location)
        @app.orogen.find_task_model(name)
      end

      private

      def known_task_names
        (library.tasks.keys + @app.orogen.each_task_model.map(&:name)).uniq.sort
      end
    end
  end
end
