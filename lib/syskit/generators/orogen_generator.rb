# frozen_string_literal: true

require 'syskit/generators/base'

module Syskit
  module Generators
    # `syskit gen orogen gps_ublox`: the Syskit extension file of a task
    # library (models/orogen/gps_ublox.rb), one extend_model block per task
    # context of its .orogen file, and its test.
    class OrogenGenerator < Base
      LIBRARY_NAME = /\A[A-Za-z_][A-Za-z0-9_]*\z/

      # What the template says of one task context; +inherited+: what the
      # extension it builds on declares (driver_for and provides lines),
      # +driven+: the device and bus models it drives through them.
      TaskInfo = Struct.new(:name, :accessor, :doc, :device_name, :property, :output_port, :dynamic_type,
                            :inherited, :driven, :bus, keyword_init: true)

      # The bus a task talks to through ports of its message type (the
      # seed's form of test for a bus device's driver): the bus model's
      # name, its short name, the example attribute calls of its attached
      # devices and the stub device's options (a read-only or write-only
      # client).
      BusInfo = Struct.new(:model, :short_name, :attributes, :options, keyword_init: true)

      # The values the generated test gives a bus attribute's parameters.
      EXAMPLE_VALUES = %w[0x100 0x7ff 1 2 3].freeze

      # The extension file an app's models/orogen/LIB.rb takes the place of:
      # its path, the require that loads it, and where it comes from.
      Base = Struct.new(:path, :require_path, :origin, keyword_init: true)

      attr_reader :library

      # +library+: the name of an .orogen file; +options+: force:, dry_run:.
      def initialize(root, library, **options)
        super(root, **options)
        @library = library.to_s
        return if LIBRARY_NAME.match?(@library)

        Name.refuse_path(@library, 'task library', 'e.g. gps_ublox')
        raise GeneratorError.new("'#{@library}' is not a task library name",
                                 hint: 'give the name of an .orogen file without its extension, e.g. gps_ublox')
      end

      # Relative path => content of the files to write. Loads the app to
      # read the task library's specification.
      def files
        spec_path, tasks, base = read_library
        @notes = base ? [base_note(base)] : []
        locals = { app_name: app_name, library: library, spec_path: spec_path, tasks: tasks, base: base,
                   modules: Template::Modules.new(app_name.split('::')) }
        {
          "models/orogen/#{library}.rb" => Template.render('orogen', **locals),
          "test/orogen/test_#{library}.rb" => Template.render('orogen_test', **locals)
        }
      end

      # The extension an app's file takes the place of, when there is one.
      def notes
        @notes || []
      end

      private

      def base_note(base)
        "models/orogen/#{library}.rb takes the place of the #{library} extension #{base.origin}: it starts with " \
          "require '#{base.require_path}', which keeps what that file declares"
      end

      # Where the .orogen file is, for the file's header, and its tasks.
      def read_library
        with_library(library) do |loaded, path, app|
          base = base_extension(app)
          # What it declares, also when the app's file it replaces (--force)
          # did not require it.
          app.load_file(base.path) if base
          [spec_description(path), task_infos(loaded, path), base]
        end
      end

      # The extension of this library in the bundles after the app (the
      # gem's own common_models last), which the app's file takes the place
      # of, as in Rock: the generated file requires it, as Rock's do
      # (require 'common_models/models/orogen/canbus').
      def base_extension(app)
        app.bundles.drop(1).each do |bundle|
          path = bundle.file("models/orogen/#{library}.rb")
          next unless path

          origin = bundle.equal?(Syskit::App::BundleSearch::BUNDLED) ? 'bundled with syskit' : "of #{bundle}"
          return Base.new(path: path, require_path: "#{bundle.require_name}/models/orogen/#{library}",
                          origin: origin)
        end
        nil
      end

      # The path of the .orogen file inside the app, no machine-specific
      # path otherwise.
      def spec_description(path)
        return path.delete_prefix("#{root}/") if path.start_with?("#{root}/")
        return "#{library}.orogen, bundled with syskit" if path.start_with?("#{Syskit::App::BUNDLED_MODELS}/")

        "#{library}.orogen, found on SYSKIT_OROGEN_PATH"
      end

      def task_infos(loaded, path)
        tasks = loaded.tasks.values.sort_by(&:name)
        if tasks.empty?
          raise GeneratorError.new("task library '#{library}' declares no task context, there is nothing to extend",
                                   location: Location.new(path, 1),
                                   hint: "declare one in #{File.basename(path)}: task_context 'Task' do ... end")
        end

        tasks.map { |model| task_info(model) }
      end

      def task_info(model)
        relative = model.name.delete_prefix("#{library}::")
        TaskInfo.new(
          name: model.name, accessor: "OroGen.#{library}.#{relative.split('::').join('.')}",
          doc: model.spec.doc, device_name: device_name(relative),
          property: (model.spec.properties.keys + model.property_declarations.keys).first,
          **port_info(model), **inherited_info(model), bus: bus_info(model)
        )
      end

      # The bus model +model+ is a client of, when it has static ports of a
      # bus's message type and drives no bus itself: the app's own bus
      # model first, then those of the bundles.
      def bus_info(model)
        return if model.driven_device_models.any?(Models::ComBusModel)

        ports = model.ports.values.reject(&:dynamic?)
        buses = Syskit::ComBus.each_submodel.select do |bus|
          bus.message_type && ports.any? { |p| p.type.name == bus.message_type.name }
        end
        bus = buses.min_by { |b| [in_app?(b.declared_at) ? 0 : 1, b.name.to_s] }
        bus && bus_description(bus, ports.select { |p| p.type.name == bus.message_type.name })
      end

      def bus_description(bus, ports)
        options = []
        options << 'bus_to_client: false' unless ports.any?(&:input?)
        options << 'client_to_bus: false' unless ports.any?(&:output?)
        attributes = bus.attached_device_configuration_modules.flat_map { |m| m.dsl_attribute_parameters.to_a }
        calls = attributes.map do |attr, params|
          count = params.count { |kind, _| %i[req opt rest].include?(kind) }
          ".#{attr}(#{EXAMPLE_VALUES.first([count, 1].max).join(', ')})"
        end
        BusInfo.new(model: bus.name, short_name: bus.name.split('::').last, attributes: calls.join,
                    options: options.map { |o| ", #{o}" }.join)
      end

      # The ports the template's examples name.
      def port_info(model)
        dynamic = model.dynamic_ports.find { |p| p.direction == :output }
        { output_port: model.ports.values.select(&:output?).min_by(&:name)&.name,
          dynamic_type: dynamic && type_expression(dynamic.type) }
      end

      # What the extension the app's builds on declares: its services, as
      # lines, and the models they drive.
      def inherited_info(model)
        inherited = model.each_data_service.select(&:master?).reject { |srv| in_app?(srv.declared_at) }
        { inherited: inherited.map { |srv| declaration_of(srv) },
          driven: inherited.filter_map(&:driven_device_model).uniq.map(&:name).sort }
      end

      # Whether a declaration is in the app's own files (an extension
      # overwritten with --force), not in the extension the app builds on.
      def in_app?(location)
        location&.path.to_s.start_with?("#{root}/")
      end

      # driver_for Model, as: 'name' / provides Model, as: 'name'
      def declaration_of(srv)
        "#{srv.model.is_a?(Models::DeviceModel) ? 'driver_for' : 'provides'} #{srv.model.name}, as: '#{srv.name}'"
      end

      # F9Task -> f9, Task -> the library's name: the 'as' of the examples.
      def device_name(relative)
        base = Naming.underscore(relative.split('::').last.delete_suffix('Task'))
        base.empty? ? library : base
      end

      # Types.canbus.Message for /canbus/Message, the name as a string for
      # names that are not Ruby method chains (containers, plain types).
      def type_expression(type)
        name = type.respond_to?(:name) ? type.name : type.to_s
        name.match?(%r{\A(/[A-Za-z_]\w*)+\z}) ? "Types#{name.tr('/', '.')}" : "'#{name}'"
      end
    end
  end
end
