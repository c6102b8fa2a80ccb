# frozen_string_literal: true

require 'yaml'
require 'syskit/generators/base'

module Syskit
  module Generators
    # `syskit gen orogenconf gps_ublox::Task`: the task's configuration file,
    # config/orogen/gps_ublox::Task.yml, with a 'default' section holding
    # every property at its initial value (the spec's default, else the
    # type's zero), each under its documentation, as Syskit's generator
    # writes it from a running component.
    class OrogenConfGenerator < Base
      ALLOWED = %w[config/orogen].freeze
      TASK_NAME = /\A[A-Za-z_]\w*(::[A-Za-z_]\w*)+\z/

      attr_reader :task_name

      # +task_name+: the task model's name, LIB::Task; +options+: force:, dry_run:.
      def initialize(root, task_name, **options)
        super(root, **options)
        @task_name = task_name.to_s
        return if TASK_NAME.match?(@task_name)

        raise GeneratorError.new("'#{@task_name}' is not the name of a task model",
                                 hint: 'give the library and the task, as in the name of the configuration ' \
                                       'file: syskit gen orogenconf gps_ublox::Task')
      end

      # Relative path => content of the file to write. Loads the app to read
      # the task's specification.
      def files
        { "config/orogen/#{task_name}.yml" => section(task_model) }
      end

      private

      def task_model
        with_library(task_name.split('::').first) { |loaded, _| loaded.tasks[task_name] || raise(unknown_task(loaded)) }
      end

      def unknown_task(library)
        names = library.tasks.keys.sort
        GeneratorError.new("task library '#{library.name}' has no task '#{task_name}'" \
                           "#{Naming.did_you_mean(task_name, names)}",
                           hint: names.empty? ? 'it declares no task context' : "its tasks are #{names.join(', ')}")
      end

      def section(model)
        properties = model.property_declarations.values.sort_by(&:name)
        header = "# Configuration of #{model.name}: one section per configuration, the 'default'\n" \
                 "# one applied first. Delete what you do not change: a section only sets the\n" \
                 "# properties it names.\n"
        body = properties.empty? ? ["# #{model.name} has no property\n"] : properties.map { |p| property_text(p) }
        "#{header}--- name:default\n#{body.join}"
      end

      # The property's documentation as comments, then its value; a value
      # syskit cannot write (an opaque type) is left commented out.
      def property_text(property)
        comment = property.doc.to_s.strip.lines.map { |l| "# #{l.rstrip}".rstrip }
        if property.type.opaque?
          value = "# #{property.name}: (#{property.type.name} is opaque to syskit, write its value here)"
        else
          plain = property.type.to_plain(property.initial_value)
          value = YAML.dump(property.name => plain).delete_prefix("---\n").chomp
        end
        [*comment, value].join("\n") << "\n"
      end
    end
  end
end
