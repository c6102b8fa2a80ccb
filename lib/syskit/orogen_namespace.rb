# frozen_string_literal: true

module Syskit
  # What the +OroGen+ constant is extended with (Syskit's
  # OroGenNamespace): +OroGen.canbus.Task+ reaches a task model by its
  # library (project) and name. Any module may be extended with it
  # (+Module.new.extend(OroGenNamespace)+) and be given models with
  # #register_syskit_model; an app's OroGen namespace (a Namespace) also
  # knows the app's task libraries through its loader, and says which
  # +using_task_library+ is missing.
  module OroGenNamespace
    # Syskit's switches to also register models as constants
    # (+OroGen::Project::Task+, and +::Project::Task+); off unless set.
    attr_writer :syskit_model_constant_registration, :syskit_model_toplevel_constant_registration

    # The task libraries of the app this namespace belongs to (see
    # Orogen::Loader), nil for a namespace made on its own.
    attr_accessor :loader

    def syskit_model_constant_registration?
      @syskit_model_constant_registration == true
    end

    def syskit_model_toplevel_constant_registration?
      @syskit_model_toplevel_constant_registration == true
    end

    # Makes +model+ reachable by its oroGen name (+model.orogen_model.name+,
    # 'project::Task' or 'project::ns::Task') as +namespace.project.Task+,
    # and returns that call chain.
    # The project is the first part of the name, as in Syskit.
    def register_syskit_model(model)
      project, *path = model.orogen_model.name.split('::')
      project_namespace(project).add(path, model)
      (@syskit_models_by_orogen_name ||= {})[model.orogen_model.name] = model
      [name || to_s, project, *path].join('.')
    end

    # Undoes #register_syskit_model: the model is no longer reachable, nor
    # its project once it has no model left.
    def deregister_syskit_model(model)
      project, *path = model.orogen_model.name.split('::')
      @syskit_models_by_orogen_name&.delete(model.orogen_model.name)
      namespace = @syskit_projects&.fetch(project, nil)
      return unless namespace

      namespace.remove(path)
      forget_project(project, namespace) if namespace.names.empty?
    end

    # Whether a model of the project +name+ was registered.
    def project_name?(name)
      !!@syskit_projects&.key?(name.to_s)
    end

    # The task model called +name+ ('logger::Logger'): registered, or of
    # a loaded library of the app.
    def syskit_model_by_orogen_name(name)
      found = @syskit_models_by_orogen_name&.fetch(name.to_s, nil) || loader&.find_task_model(name.to_s)
      return found if found

      raise unknown_model(name) if loader

      raise DeclarationError.new("#{name} is not registered on #{self}", location: Location.of_caller,
                                                                         hint: 'register it with register_syskit_model')
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
        cause = loader&.failed_user_of(name)
        raise (cause ? FollowOnError : FileLoadError).new(
          "task library '#{name}' is not loaded (loaded: #{loaded_list})#{", as #{cause} failed" if cause}",
          location: Location.of_caller, hint: "add using_task_library '#{name}' before using OroGen.#{name}"
        )
      end
    end

    # +name+ is a method name (OroGen.gps_ubox) or a constant name
    # (OroGen::GpsUblox, of a library that is not loaded).
    def explain_missing(name)
      return super unless loader

      available = loader.available_library_names
      library = available.find { |lib| Namespace.constant_for(lib) == name }
      if library
        return ["task library '#{library}' is not loaded (loaded: #{loaded_list})",
                "add using_task_library '#{library}' before using OroGen::#{name}"]
      end

      ["there is no task library '#{name}'#{Naming.did_you_mean(name, available)} (loaded: #{loaded_list})",
       "available task libraries: #{available.join(', ')}; load one with using_task_library 'name'"]
    end

    # Forgets the app's libraries and the registered models.
    def forget
      super if defined?(super)
      @loader = nil
      @syskit_projects = nil
      @syskit_models_by_orogen_name = nil
    end

    private

    # The namespace of the project +project+, made on first use: a method
    # of this one, and a constant when Syskit's constant registration is on.
    def project_namespace(project)
      @syskit_projects ||= {}
      @syskit_projects.fetch(project) do
        namespace = Namespace.new(name || to_s, [project])
        @syskit_projects[project] = namespace
        define_singleton_method(project) { namespace } if project.match?(/\A[a-z_]\w*\z/)
        if syskit_model_constant_registration?
          register_project_constant(self, project, namespace)
          register_project_constant(Object, project, namespace) if syskit_model_toplevel_constant_registration?
        end
        namespace
      end
    end

    # +OroGen::Project+ (and +::Project+ with the toplevel registration)
    # is the project's namespace, unless the constant exists already.
    def register_project_constant(owner, project, namespace)
      constant = Namespace.constant_for(project)
      owner.const_set(constant, namespace) if constant && !owner.const_defined?(constant, false)
    end

    def forget_project(project, namespace)
      @syskit_projects.delete(project)
      singleton_class.send(:remove_method, project) if singleton_class.method_defined?(project, false)
      constant = Namespace.constant_for(project)
      [self, Object].each do |owner|
        next unless constant && owner.const_defined?(constant, false) && owner.const_get(constant).equal?(namespace)

        owner.send(:remove_const, constant)
      end
    end

    def unknown_model(name)
      FileLoadError.new("there is no loaded task model '#{name}' (loaded libraries: #{loaded_list})",
                        location: Location.of_caller,
                        hint: "load its library with using_task_library '#{name.to_s.split('::').first}'")
    end

    def loaded_list
      names = loader.loaded_library_names
      names.empty? ? 'none' : names.join(', ')
    end
  end
end
