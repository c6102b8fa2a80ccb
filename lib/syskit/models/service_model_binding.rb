# frozen_string_literal: true

module Syskit
  module Models
    # What a data service model says of the components that provide it, as
    # Syskit's service models do: a component model's (or a task's) service
    # of this model (+Pose.bind(Task)+), the placeholder standing for "any
    # component providing it", and, for devices, the loaded task models
    # that drive it. Part of DataServiceModel.
    module ServiceModelBinding
      # The service of +component+ (a component model, or one of its
      # services) that is or provides this model, seen as this model; nil
      # if it has none or several.
      def try_bind(component)
        return component.as(self) if component.is_a?(BoundDataService) && component.fullfills?(self)
        return unless component.respond_to?(:find_all_data_services_from_type)

        found = component.find_all_data_services_from_type(self)
        found.first if found.size == 1
      end

      # As #try_bind, but an error saying why there is no single service.
      def bind(component)
        found = try_bind(component)
        return found if found

        raise unbound(component, Location.of_caller)
      end
      alias resolve bind
      alias try_resolve try_bind

      # Why +component+ has no single service of this model.
      def unbound(component, location)
        services = []
        if component.respond_to?(:find_all_data_services_from_type)
          services = component.find_all_data_services_from_type(self)
        end
        if services.empty?
          return DeclarationError.new("#{component.inspect} provides no service of type #{self}",
                                      location: location, hint: "give a component that provides #{self}")
        end

        names = services.map(&:full_name).sort
        AmbiguousServiceSelection.new("#{component.inspect} has several services of type #{self}: #{names.join(', ')}",
                                      location: location,
                                      hint: "choose one by its name: #{component.inspect}.#{names.first}_srv")
      end

      # The abstract task model standing for any component providing this
      # model (see Placeholder), made once.
      def placeholder_model
        @placeholder_model ||= Placeholder.for([self])
      end

      # A task of the placeholder model: an abstract task standing for a
      # component providing this model (a test's child, a plan's hole).
      def create_placeholder_task(**arguments)
        placeholder_model.new(arguments)
      end

      # The component models (not abstract) that drive this device model,
      # by name: the loaded task libraries' and those made in Ruby
      # (+TaskContext.new_submodel { driver_for Dev, as: 'x' }+), as Syskit
      # finds them among Syskit::Component's submodels.
      def find_all_drivers
        app = Syskit.app
        indexed = app ? app.orogen.current_driver_index.drivers_for(self) : []
        made = Syskit::Component.each_submodel.select { |m| !m.abstract? && m.fullfills?(self) }
        (indexed | made).sort_by(&:to_s)
      end

      # The only component model driving this device model; Syskit's
      # Ambiguous when there are several, an ArgumentError when none.
      def default_driver
        drivers = find_all_drivers
        return drivers.first if drivers.size == 1

        location = Location.of_caller
        if drivers.empty?
          raise DeclarationError.new("no loaded task model drives #{self}",
                                     location: location, hint: "load its driver's task library (using_task_library)")
        end

        raise Ambiguous.new("several task models drive (#{drivers.join(', ')}) #{self}",
                            location: location, hint: 'pick one')
      end
    end
  end
end
