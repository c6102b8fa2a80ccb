# frozen_string_literal: true

module Syskit
  module Network
    # The errors of instantiation that say what to select, and where.
    module InstantiationErrors
      module_function

      # Nothing concrete is selected for what +requirements+ ask at +path+
      # (a child of +parent+, or a root); +model+: an abstract composition.
      def abstract_child(requirements, path, parent, location, model = nil)
        tag = requirements.name if requirements.name&.end_with?('_tag')
        # A tag is shown by the services it stands for, then named.
        what = model || (tag ? requirements.profile.find_tag(tag).models : requirements.models).join(', ')
        role = path.split('.').last
        where = parent ? "the child '#{role}' of #{parent.model} (#{path})" : path
        message = "#{where} needs a #{what}, which is abstract, and nothing selects a component for it" \
                  "#{" (#{requirements.profile&.name}.#{tag} selects nothing)" if tag}"
        hint = abstract_hint(requirements, role, parent, tag, model)
        if tag
          return UnselectedTag.new(message, profile: requirements.profile, abstract: requirements, location: location,
                                            hint: hint)
        end

        TaskAllocationFailed.new(message, abstract: model || requirements, location: location, hint: hint)
      end

      def abstract_hint(requirements, role, parent, tag, model)
        if tag
          "select one in the profile: use(#{requirements.profile&.name}.#{tag} => Model), " \
            "or where it is used: use_profile #{requirements.profile&.name}, '#{tag.delete_suffix('_tag')}' => Model"
        elsif model
          "use a concrete submodel of #{model}, or select children that one of its specializations applies to"
        elsif parent
          "select one: #{parent.model}.use('#{role}' => Model) (a task or composition model providing " \
            "#{requirements.models.join(' and ')}, a device, or a definition)"
        else
          "plan a concrete model, or select one with use(#{requirements.models.first} => Model) in the profile"
        end
      end

      # A driver task model put in a network with no device for it.
      def no_device(model, path, parent, location)
        srv = model.driver_services.first
        role = path.split('.').last
        select = parent ? "#{parent.model}.use('#{role}' => Base.x_dev)" : "Base.x_dev (the device's action)"
        NetworkError.new(
          "#{parent ? "the child '#{role}' of #{parent.model} (#{path})" : path} is a #{model.name}, " \
          "which drives a #{srv.driven_device_model}, but no device is selected for it",
          location: location,
          hint: "select the device it drives: #{select}, or declare a single #{srv.driven_device_model} " \
                'in the robot block so that the profile selects it'
        )
      end
    end
  end
end
