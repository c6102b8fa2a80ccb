# frozen_string_literal: true

module Syskit
  # Whether one task held in a plan may stand for another, and making it
  # do so, as Syskit's components answer +can_merge?+ and +merge+ (the
  # models' side is Models::ComponentMerging). Part of Component.
  module ComponentMerging
    # Whether this task may stand for +other+ too: an abstract task cannot
    # take a concrete one's place, their models must merge (services of one
    # name of one model), and arguments both have set must be equal.
    def can_merge?(other)
      return false if abstract? && !other.abstract?
      return false unless model.can_merge?(other.model)

      other.arguments.all? do |key, value|
        !arguments.set?(key) || !other.arguments.set?(key) || arguments[key] == value
      end
    end

    # Makes this task stand for +other+ too: it takes the arguments +other+
    # has set and it has not, and the services +other+ required from
    # dynamic services that it lacks (on its own model, see #specialize, so
    # that its model is left as it is). Returns the task.
    def merge(other)
      other.arguments.each_key do |key|
        arguments[key] = other.arguments[key] if merged_argument?(other.arguments, key)
      end
      merge_required_dynamic_services(other)
      self
    end

    private

    # Whether the argument +key+ of +given+ replaces the task's: a set one
    # replaces what is not set, a default one only what is not there at
    # all (Roby::DefaultArgument).
    def merged_argument?(given, key)
      return !arguments.set?(key) if given.set?(key)

      given[key].is_a?(Compat::Roby::DefaultArgument) && !arguments.key?(key)
    end

    def merge_required_dynamic_services(other)
      return unless other.respond_to?(:each_required_dynamic_service)

      other.each_required_dynamic_service.each do |srv|
        next if model.find_data_service(srv.full_name)

        require_dynamic_service(srv.model.dynamic_service.name, as: srv.full_name,
                                                                **srv.model.dynamic_service_options)
      end
    end
  end
end
