# frozen_string_literal: true

module Syskit
  # Statements available in any module body (and, for the ones that make
  # sense there, at the top level of a file), as in the seed's snippets.
  module DSL
    # Statements of the top level of a file (+using_task_library+ above
    # +module MyApp+, as in the seed).
    module TopLevelStatements
      include Types::TypeNames

      private

      def using_task_library(name)
        DSL.app!.using_task_library(name.to_s, location: Location.of_caller)
      end

      def import_types_from(name)
        DSL.app!.import_types(name.to_s, location: Location.of_caller)
      end

      # A file of the app or of its bundles is loaded by the app (see
      # App::Files#required_file), the one the load path finds first even
      # when another bundle's file of that name is loaded. A Ruby library of
      # Rock's runtime that is not installed here is not modelled: requiring
      # it is a warning, and the file goes on loading; common_models' old
      # name is mapped (see Compat::OldCommonModels).
      def require(name)
        path = Syskit.app&.required_file(name) if name.is_a?(String)
        if path
          Syskit.app.record_require(Location.of_caller, path)
          return Syskit.app.load_file(path)
        end

        super
      rescue LoadError
        return Compat.require_provided(name) if Compat.provided_library?(name)
        raise unless Syskit.app

        old = Compat::OldCommonModels
        return old.require_instead(name, Location.of_caller) if old.require_path?(name)
        raise unless Compat.runtime_library?(name)

        Syskit.app.not_modelled("the Ruby library '#{name}' (part of Rock's runtime)", Location.of_caller)
        false
      end
    end

    # Model definitions. Included in Module; public, as in Syskit (Rock's
    # bundles call +Services.data_service_type+ from helper methods).
    module ModuleStatements
      include TopLevelStatements

      # +data_service_type 'Pose' do output_port 'pose', '/base/Pose' end+;
      # +parent:+ gives a service model whose class (a
      # Syskit::Models::DataServiceModel subclass) and API to use.
      def data_service_type(name, parent: Syskit::DataService, &block)
        location = Location.of_caller
        unless parent.is_a?(Models::DataServiceModel) && !parent.is_a?(Models::DeviceModel)
          raise DeclarationError.new("parent: expects a data service model, got #{parent.inspect}",
                                     location: location,
                                     hint: 'pass a model declared with data_service_type, or an instance of a ' \
                                           'Syskit::Models::DataServiceModel subclass')
        end

        Models::DataServiceModel.define(self, name, location: location, root: parent, model_class: parent.class, &block)
      end

      # +device_type 'F9' do provides ... end+; +parent:+ gives a device model
      # whose class (a Syskit::Models::DeviceModel subclass) and API to use.
      def device_type(name, parent: Syskit::Device, &block)
        location = Location.of_caller
        unless parent.is_a?(Models::DeviceModel) && !parent.is_a?(Models::ComBusModel)
          raise DeclarationError.new("parent: expects a device model, got #{parent.inspect}",
                                     location: location,
                                     hint: 'pass an instance of a Syskit::Models::DeviceModel subclass')
        end

        Models::DeviceModel.define(self, name, location: location, root: parent, model_class: parent.class, &block)
      end

      # +com_bus_type 'CAN', message_type: '/canbus/Message' do ... end+;
      # also +lazy_dispatch:+ and +override_policy:+ (see ComBusModel).
      def com_bus_type(name, message_type: nil, **options, &block)
        Models::ComBusModel.define(self, name, location: Location.of_caller, root: Syskit::ComBus,
                                               message_type: message_type, **options, &block)
      end

      # +profile 'Base' do robot do ... end end+ defines the constant Base.
      def profile(name, &block)
        location = Location.of_caller
        mod = profile_module(name.to_s, location)
        Actions::Profile.for_module(mod, location)
        mod.module_eval(&block) if block
        mod
      end

      # A robot block in a module makes the module a profile.
      def robot(&)
        Actions::Profile.for_module(self, Location.of_caller).robot_block(&)
      end

      private

      def profile_module(name, location)
        unless Naming.constant_name?(name)
          raise DeclarationError.new("'#{name}' is not a valid profile name",
                                     location: location, hint: "profile names are constant names, e.g. profile 'Base'")
        end
        return const_set(name, Module.new) unless const_defined?(name, false)

        existing = const_get(name, false)
        return existing if existing.instance_of?(Module)

        raise DeclarationError.new("#{self}::#{name} is already defined and is not a profile",
                                   location: location, hint: 'give the profile another name')
      end
    end

    def self.app!
      Syskit.app || raise(Error.new('no Syskit app is loaded',
                                    location: Location.of_caller,
                                    hint: 'load the file through syskit (syskit check, syskit plan, rake test)'))
    end
  end
end
