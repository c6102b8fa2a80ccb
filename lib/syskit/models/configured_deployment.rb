# frozen_string_literal: true

module Syskit
  module Models
    # A deployment model as a robot configuration uses it: on a process
    # server (+on:+), its tasks renamed (+name_mappings+: deployed name =>
    # name on the robot), some of them read only (+read_only:+ names or
    # patterns of renamed tasks). Its +orogen_model+ is the renamed spec;
    # the model's own is left as it is.
    class ConfiguredDeployment
      attr_reader :process_server_name, :model, :name_mappings, :process_name, :read_only

      # +read_only:+ true for all tasks, or names and patterns. Mappings
      # written without braces (+'test' => 'left_test'+) are mappings too.
      def initialize(process_server_name, model, name_mappings = {}, process_name = model.deployment_name,
                     read_only: [], **more_mappings)
        @process_server_name = process_server_name
        @model = model
        @name_mappings = model.orogen_model.task_activities.to_h { |t| [t.name, t.name] }
                              .merge(name_mappings, more_mappings.transform_keys(&:to_s))
        @process_name = process_name
        @read_only = read_only == true ? @name_mappings.values : resolve_read_only(Array(read_only || []))
      end

      # The deployment's spec with its tasks renamed.
      def orogen_model
        @orogen_model ||= model.orogen_model.with_name_mappings(name_mappings, name: process_name)
      end

      # The deployment as it would run (Syskit::Deployment), with its
      # process server, name mappings and read-only tasks as arguments.
      def new
        model.new(on: process_server_name, name_mappings: name_mappings, process_name: process_name,
                  read_only: read_only)
      end

      private

      # The renamed tasks that +patterns+ (names or regexps) designate.
      def resolve_read_only(patterns)
        names = name_mappings.values
        found = names.select { |name| patterns.any? { |pattern| pattern === name } } # rubocop:disable Style/CaseEquality -- a name or a Regexp
        return found if patterns.empty? || !found.empty?

        raise DeclarationError.new(
          "#{patterns} is not a valid deployed task name or pattern. The valid deployed task names are #{names}.",
          location: Location.of_caller, hint: "read_only: takes names among #{names.join(', ')}, or regexps"
        )
      end
    end
  end
end
