# frozen_string_literal: true

module Syskit
  module Queries
    # The +name_srv+ and +name_port+ readers of a matcher, from the models
    # it matches (+Task.match.gps_srv.pose_port+): each returns a narrower
    # matcher. They are defined as the models are given, so that a name no
    # model has raises NoMethodError, as any unknown method does.
    module Accessors
      # The models the matcher resolves names against.
      def matched_models
        @models
      end

      # The port model +name+ of the matched models; nil when none has it,
      # Ambiguous when several do.
      def find_port_by_name(name)
        ports = matched_models.filter_map { |m| m.find_port(name) }
        return ports.first if ports.size <= 1

        raise Ambiguous,
              "more than one port named '#{name}' exist on composite model " \
              "#{matched_models.join(', ')}. Select a data service explicitly to disambiguate"
      end

      # A PortMatcher for the port +name+ on what this matcher finds.
      def find_port_matcher_by_name(name)
        return unless (port = find_port_by_name(name))

        PortMatcher.new(self).with_name(name).with_type(port.type)
      end

      # The service model +name+ of the matched models, nil if none.
      def find_data_service_by_name(name)
        matched_models.each do |m|
          srv = m.find_data_service(name) if m.respond_to?(:find_data_service)
          return srv if srv
        end
        nil
      end

      # A DataServiceMatcher for the service +name+ on what this matcher finds.
      def find_data_service_matcher_by_name(name)
        return unless (srv = find_data_service_by_name(name))

        DataServiceMatcher.new(self).with_name(name).with_model(srv.model)
      end

      private

      def define_accessors
        matched_models.each do |m|
          m.each_port { |p| define_singleton_method(:"#{p.name}_port") { find_port_matcher_by_name(p.name) } }
          next unless m.respond_to?(:each_data_service) && m.is_a?(Class)

          m.each_data_service do |srv|
            define_singleton_method(:"#{srv.full_name}_srv") { find_data_service_matcher_by_name(srv.full_name) }
          end
        end
      end
    end
  end
end
