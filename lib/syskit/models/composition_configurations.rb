# frozen_string_literal: true

module Syskit
  module Models
    # The named configurations of composition models: which configuration
    # sections each child gets when the composition is used with a
    # configuration of its own. Part of Composition.
    module CompositionConfigurations
      # Named configurations: +conf 'slow', controller_child => ['default', 'slow']+
      # gives the children these sections when the composition is used
      # with_conf('slow').
      def conf(name, mappings = {})
        location = Location.of_caller
        sections = mappings.to_h do |child, confs|
          child_name = child.respond_to?(:child_name) ? child.child_name : child.to_s
          unless find_child(child_name)
            raise DeclarationError.new("conf '#{name}' names #{child_name}, which is not a child of #{self}",
                                       location: location, hint: "children are #{child_names.join(', ')}")
          end

          [child_name, Array(confs).map(&:to_s).freeze]
        end
        (@configuration_locations ||= {})[name.to_s] = location
        (@configurations ||= {})[name.to_s] = sections.freeze
      end

      # Named configurations (see #conf), inherited ones included.
      def configurations
        inherited = superclass.respond_to?(:configurations) ? superclass.configurations : {}
        inherited.merge(@configurations || {})
      end

      # The configuration +name+ (child name => sections), nil when there
      # is none: #configurations[name] without merging the hierarchy's
      # (asked for each child of each composition while generating).
      def configuration(name)
        found = @configurations&.[](name)
        return found if found

        superclass.configuration(name) if superclass.respond_to?(:configuration)
      end

      # Where the named configuration +name+ is declared.
      def configuration_location(name)
        @configuration_locations&.[](name) ||
          (superclass.configuration_location(name) if superclass.respond_to?(:configuration_location))
      end
    end
  end
end
