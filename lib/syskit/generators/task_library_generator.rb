# frozen_string_literal: true

require 'syskit/generators/orogen_generator'

module Syskit
  module Generators
    # `syskit gen tasklib gps_ublox` (or gps_ublox::F9Task): a new task
    # library, models/orogen/gps_ublox.orogen, with one task context to
    # fill in, and the extension file and test `gen orogen` would write for
    # it. What a Rock driver package's .orogen declares, before there is
    # one to extend.
    class TaskLibraryGenerator < Base
      NAME = /\A(?<library>[A-Za-z_][A-Za-z0-9_]*)(?:::(?<task>[A-Z][A-Za-z0-9_]*))?\z/
      # The property and output port the new task context declares, which
      # the extension's examples use.
      PROPERTY = 'device'
      OUTPUT_PORT = 'samples'

      attr_reader :library, :task

      # +name+: LIB or LIB::TASK (the task context, Task by default);
      # +options+: force:, dry_run:.
      def initialize(root, name, **options)
        super(root, **options)
        match = NAME.match(name.to_s)
        raise invalid_name(name.to_s) unless match

        @library = match[:library]
        @task = match[:task] || 'Task'
        check_not_elsewhere
      end

      # Relative path => content of the files to write.
      def files
        spec_path = "models/orogen/#{library}.orogen"
        locals = { app_name: app_name, library: library, spec_path: spec_path, tasks: [task_info], base: nil,
                   task: task, property: PROPERTY, output_port: OUTPUT_PORT, robot: app_name }
        {
          spec_path => Template.render('task_library', **locals),
          "models/orogen/#{library}.rb" => Template.render('orogen', **locals),
          "test/orogen/test_#{library}.rb" => Template.render('orogen_test', **locals)
        }
      end

      private

      # What the extension and test templates say of the new task context.
      def task_info
        OrogenGenerator::TaskInfo.new(
          name: "#{library}::#{task}", accessor: "OroGen.#{library}.#{task}", doc: nil,
          device_name: task == 'Task' ? library : Naming.underscore(task.delete_suffix('Task')),
          property: PROPERTY, output_port: OUTPUT_PORT, dynamic_type: nil, inherited: [], driven: []
        )
      end

      def invalid_name(name)
        Name.refuse_path(name, 'task library', 'e.g. gps_ublox or gps_ublox::F9Task')
        library, task = name.split('::', 2)
        if task && OrogenGenerator::LIBRARY_NAME.match?(library)
          return GeneratorError.new("'#{task}' is not a task context name",
                                    hint: 'task contexts are named as Ruby constants, e.g. gps_ublox::F9Task')
        end

        GeneratorError.new("'#{name}' is not a task library name",
                           hint: 'give a name of letters, digits and _ (the .orogen file is named after it), ' \
                                 'and optionally its task context: gps_ublox or gps_ublox::F9Task')
      end

      # A library of that name elsewhere on the search path (bundled with
      # syskit, in a bundle, on SYSKIT_OROGEN_PATH) would be hidden by the
      # new one; one in the app is the file writer's (--force).
      def check_not_elsewhere
        app = Syskit::App.new(root)
        existing = app.orogen_search_dirs.map { |dir| File.join(dir, "#{library}.orogen") }.find { |p| File.file?(p) }
        return if existing.nil? || existing.start_with?("#{root}/")

        where = if existing.start_with?("#{Syskit::App::BUNDLED_MODELS}/") then 'bundled with syskit'
                else Location.new(existing, nil).relative_path(root)
                end
        raise GeneratorError.new(
          "there is already a task library '#{library}' (#{where}): a new one in the app would hide it",
          hint: "give the new library another name, or extend this one with: syskit gen orogen #{library}"
        )
      end
    end
  end
end
