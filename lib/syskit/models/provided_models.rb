# frozen_string_literal: true

require 'syskit/models/fullfillment'
require 'syskit/models/provided_ports'

module Syskit
  # How +provides+ and +driver_for+ read port mappings (see Models.normalize_mappings).
  module Models
    # The models a service, device or bus model provides (+provides Pose+)
    # and what follows from them: which models it fullfills, in Syskit's
    # order, its port names as each of them knows them, and the views
    # cached on that hierarchy. Part of DataServiceModel.
    module ProvidedModels
      # Whether this model is +model+ or provides it, directly or not.
      include Fullfillment

      # Methods of the model classes.
      module ClassMethods
        # Bumped whenever a data service model gains a parent (+provides+) or
        # a device configuration: the views cached on models (see
        # #hierarchy_view) are then computed again.
        def hierarchy_version
          DataServiceModel.instance_variable_get(:@hierarchy_version) || 0
        end

        def hierarchy_changed
          DataServiceModel.instance_variable_set(:@hierarchy_version, hierarchy_version + 1)
        end
      end

      def self.included(base)
        base.extend(ClassMethods)
      end

      # Declares that this model provides +model+: its ports become ours. As
      # in Syskit, +mappings+ (+'their_port' => 'our_port'+) bind a port of
      # +model+ to a port this model already has, and a port of +model+ named
      # like one of ours must be mapped explicitly, even to itself.
      def provides(model, mappings = {})
        location = Location.of_caller
        check_provides(model, location)
        return self if @parents.key?(model)

        renames = Models.normalize_mappings(model, mappings, location, owner: self, error_class: SpecError)
        adopted = ProvidedPorts.new(self, model, renames, location).adopt
        @parents[model] = adopted
        @fullfilled_models = nil
        @identity_mappings = nil
        DataServiceModel.hierarchy_changed
        self
      end

      # Forgets what the model declares, its ports and the models it
      # provides, as MetaRuby's +clear_model+ does before a model's file is
      # loaded again (which then provides them anew).
      def clear_model
        @ports = {}
        @parents = {}
        @fullfilled_models = nil
        @identity_mappings = nil
        DataServiceModel.hierarchy_changed
        self
      end

      # The models this one provides, directly or not (Syskit's
      # +parent_models+), in the order of #fullfilled_models.
      def parent_models
        fullfilled_models.drop(1)
      end

      # Whether this model provides +model+, directly or not (Syskit's
      # +provides?+: a model does not provide itself).
      def provides?(model)
        !equal?(model) && fullfills?(model)
      end

      # Ruby's comparisons of modules, as Syskit's service models answer
      # them (they include what they provide): +Odometry <= Pose+.
      def <=(other)
        other.is_a?(ProvidedModels) ? fullfills?(other) : super
      end

      def <(other)
        other.is_a?(ProvidedModels) ? provides?(other) : super
      end

      def >=(other)
        other.is_a?(ProvidedModels) ? other.fullfills?(self) : super
      end

      def >(other)
        other.is_a?(ProvidedModels) ? other.provides?(self) : super
      end

      # This model and every model it provides, in the order Syskit lists
      # them (Ruby's ancestors when models include what they provide): the
      # model, what it provided last first, the roots (Device, DataService)
      # last.
      def fullfilled_models
        @fullfilled_models ||= parents.each_key.with_object([self]) do |parent, chain|
          at = 0
          parent.fullfilled_models.each do |m|
            found = chain.index(m)
            found ? at = found : chain.insert(at += 1, m)
          end
        end.freeze
      end

      # What the block computes from this model's hierarchy (frozen),
      # computed again once any model's hierarchy changed: every device
      # declaration asks its model and its bus model for their
      # configuration modules, which do not change while a robot is
      # declared.
      #
      # With +subkey+, one value per +subkey+ (compared by identity) under
      # +name+, as Component#cached keeps them.
      def hierarchy_view(name, subkey = nil)
        version = DataServiceModel.hierarchy_version
        if @hierarchy_views_version != version
          @hierarchy_views = {}
          @hierarchy_views_version = version
        end
        table = subkey.nil? ? @hierarchy_views : (@hierarchy_views[name] ||= {}.compare_by_identity)
        slot = subkey.nil? ? name : subkey
        table.fetch(slot) { table[slot] = yield.freeze }
      end

      # Enumerates {#fullfilled_models}.
      def each_fullfilled_model(&block)
        return enum_for(__method__) unless block

        fullfilled_models.each(&block)
      end

      # For a model this one provides, its port names mapped to ours.
      # Generation asks for them once per device: they are kept (frozen)
      # until any model's hierarchy changes.
      def port_mappings_for(model)
        return (@identity_mappings ||= ports.keys.to_h { |n| [n, n] }.freeze) if model.equal?(self)

        hierarchy_view(:port_mappings, model) { inherited_port_mappings(model) }
      end

      private

      def inherited_port_mappings(model)
        parents.each do |parent, mapping|
          next unless parent.fullfills?(model)

          return parent.port_mappings_for(model).transform_values { |name| mapping.fetch(name) }
        end
        raise ArgumentError, "#{self} does not provide #{model}"
      end

      # What a model of this kind may provide.
      def check_provides(model, location)
        unless model.is_a?(DataServiceModel)
          raise DeclarationError.new(
            "provides expects a data service, device or bus model, got #{model.inspect}",
            location: location, hint: 'pass a model defined with data_service_type or device_type'
          )
        end
        return unless model.is_a?(DeviceModel) && !is_a?(DeviceModel)

        raise DeclarationError.new(
          "#{self} is a data service and cannot provide the device #{model}",
          location: location, hint: 'only devices provide devices: declare it with device_type'
        )
      end
    end

    # Port mappings given to +provides+ or +driver_for+, as +{their_port =>
    # our_port}+. Either side may name the provided model's port (the seed
    # writes both orders); aliases such as 'bus_in' for 'from_bus' are known.
    # A mapping naming no port of +model+ raises +error_class+.
    def self.normalize_mappings(model, mappings, location, owner:, error_class: DeclarationError)
      mappings.to_h do |a, b|
        a = a.to_s
        b = b.to_s
        if (name = model.port_name_for(a)) then [name, b]
        elsif (name = model.port_name_for(b)) then [name, a]
        else
          raise error_class.new(
            "#{model} has no port named '#{a}' or '#{b}' (mapping '#{a}' => '#{b}' on #{owner})",
            location: location,
            hint: "#{model}'s ports are #{model.ports.values.join(', ')}; " \
                  "write '#{model.ports.keys.first || 'its_port'}' => 'your_port'"
          )
        end
      end
    end
  end
end
