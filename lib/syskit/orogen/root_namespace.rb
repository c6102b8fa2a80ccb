# frozen_string_literal: true

module Syskit
  module Orogen
    # The object behind the +OroGen+ constant: +OroGen.canbus+ is the loaded
    # canbus library's namespace, +OroGen.extend_task+ extends a task model.
    class RootNamespace < Syskit::Namespace
      def initialize(loader)
        super('OroGen')
        @loader = loader
        const_set(:Spec, Compat::OrogenSpec)
      end

      def forget
        super
        @loader = nil
      end

      # The task model called +name+ ('logger::Logger'), as Syskit's
      # OroGen.syskit_model_by_orogen_name; its library must be loaded.
      def syskit_model_by_orogen_name(name)
        found = @loader.find_task_model(name.to_s)
        return found if found

        raise FileLoadError.new("there is no loaded task model '#{name}' (loaded libraries: #{loaded_list})",
                                location: Location.of_caller,
                                hint: "load its library with using_task_library '#{name.to_s.split('::').first}'")
      end

      # Same as Syskit.extend_model.
      def extend_task(model, &)
        Syskit.extend_model(model, &)
      end

      # A library that exists on the search path but is not loaded yet: using
      # it says which using_task_library is missing.
      def add_unloaded(name)
        return unless name.match?(/\A[a-z_]\w*\z/) && !respond_to?(name)

        define_singleton_method(name) do
          raise FileLoadError.new(
            "task library '#{name}' is not loaded (loaded: #{loaded_list})",
            location: Location.of_caller, hint: "add using_task_library '#{name}' before using OroGen.#{name}"
          )
        end
      end

      # +name+ is a method name (OroGen.gps_ubox) or a constant name
      # (OroGen::GpsUblox, of a library that is not loaded).
      def explain_missing(name)
        available = @loader.available_library_names
        library = available.find { |lib| Namespace.constant_for(lib) == name }
        if library
          return ["task library '#{library}' is not loaded (loaded: #{loaded_list})",
                  "add using_task_library '#{library}' before using OroGen::#{name}"]
        end

        ["there is no task library '#{name}'#{Naming.did_you_mean(name, available)} (loaded: #{loaded_list})",
         "available task libraries: #{available.join(', ')}; load one with using_task_library 'name'"]
      end

      private

      def loaded_list
        names = @loader.loaded_library_names
        names.empty? ? 'none' : names.join(', ')
      end
    end
  end
end
