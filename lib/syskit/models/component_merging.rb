# frozen_string_literal: true

module Syskit
  module Models
    # Whether two component models may stand for one task, and which model
    # that task has, as Syskit's component models answer: +can_merge?+ and
    # +merge+. Part of Component.
    module ComponentMerging
      # Whether a task of +target_model+ may stand for a task of this model:
      # it fullfills this model (the models specializations were made from,
      # for specializations), and the services of the same name they both
      # have are of one model, with the same options when both come from
      # dynamic services.
      def can_merge?(target_model)
        self_real = concrete_model
        target_real = target_model.concrete_model
        if !self_real.equal?(self) || !target_real.equal?(target_model)
          return false unless self_real.can_merge?(target_real)
        elsif !target_model.fullfills?(self)
          return false
        end

        each_data_service.all? do |srv|
          target_srv = target_model.find_data_service(srv.full_name)
          !target_srv || mergeable_services?(srv, target_srv)
        end
      end

      # The model of a task standing for both this model and +other+: the
      # more specific of the two (a placeholder or a service of one merges
      # itself).
      def merge(other)
        return other.merge(self) if other.is_a?(BoundDataService) || other.placeholder?
        return self if self <= other
        return other if other <= self
        return merge_private_specializations(other) if private_specialization? || other.private_specialization?

        merged = merged_specializations(other)
        return merged if merged

        raise IncompatibleComponentModels.new("cannot merge #{self} and #{other}: neither derives from the other",
                                              location: Location.of_caller,
                                              hint: 'a task has one model: choose models that derive from one another')
      end

      # The model tasks of this one are deployed as: itself (task models'
      # specializations say otherwise, see TaskSpecialization).
      def concrete_model
        self
      end

      # This model with the services +from+ required of dynamic services
      # that it lacks, required on a specialization of it when
      # +specialize_if_needed+ (else on itself), as Syskit's
      # +apply_missing_dynamic_services_from+.
      def apply_missing_dynamic_services_from(from, specialize_if_needed)
        missing = from.each_required_dynamic_service.reject { |srv| find_data_service(srv.full_name) }
        return self if missing.empty?

        model = specialize_if_needed ? specialize : self
        missing.each do |srv|
          model.require_dynamic_service(srv.dynamic_service.name, as: srv.full_name, **srv.dynamic_service_options)
        end
        model
      end

      private

      # Two specializations (see TaskSpecialization) merge into one new
      # specialization of their merged concrete models, with the dynamic
      # services both required.
      def merge_private_specializations(other)
        base = concrete_model.merge(other.concrete_model)
        result = base.apply_missing_dynamic_services_from(self, true)
        result.apply_missing_dynamic_services_from(other, base.equal?(result))
      end

      # The model made of this one's and +other+'s specializations, when
      # both specialize one model (see CompositionSpecializations).
      def merged_specializations(_other); end

      def mergeable_services?(srv, target_srv)
        return false unless srv.model.equal?(target_srv.model)
        return true unless srv.dynamic? && target_srv.dynamic?

        srv.dynamic_service_options == target_srv.dynamic_service_options
      end
    end
  end
end
