# frozen_string_literal: true

module Syskit
  module Queries
    # Finds the services (Syskit::BoundDataService) of the components a
    # ComponentMatcher finds, by name and service model, each seen as the
    # matched model (+Task.gps_srv.match.as(Srv)+).
    class DataServiceMatcher
      include PlanResults
      include Accessors

      def initialize(component_matcher)
        @component_matcher = component_matcher
        @name_filter = nil
        with_model(Syskit::DataService)
      end

      # The service model the matched services are seen as.
      def data_service_model
        @models.first
      end

      # Matches the services of this name only.
      def with_name(name)
        @name_filter = name
        self
      end

      # Matches the services that fullfill +model+, seen as +model+.
      def with_model(model)
        @models = [model]
        define_accessors
        self
      end

      # Sees the matched services as +model+, which the current model must
      # provide; ArgumentError otherwise.
      def as(model)
        unless data_service_model.fullfills?(model)
          raise ArgumentError, "cannot refine match from #{data_service_model} to #{model}"
        end

        with_model(model)
      end

      # Narrows the components whose services are matched (see
      # ComponentMatcher).
      %i[abstract not_abstract with_arguments].each do |predicate|
        define_method(predicate) do |*args, **options|
          @component_matcher.public_send(predicate, *args, **options)
          self
        end
      end

      def match
        self
      end

      def ===(service)
        service.is_a?(BoundDataService) &&
          (!@name_filter || @name_filter === service.full_name) && # rubocop:disable Style/CaseEquality
          service.fullfills?(data_service_model) &&
          @component_matcher === service.component # rubocop:disable Style/CaseEquality
      end

      # Yields the matching services of the components of +plan+.
      def each_in_plan(plan)
        return enum_for(__method__, plan) unless block_given?

        @component_matcher.each_in_plan(plan) do |task|
          task.each_data_service do |srv|
            yield(srv.as(data_service_model)) if self === srv # rubocop:disable Style/CaseEquality
          end
        end
      end
    end
  end
end
