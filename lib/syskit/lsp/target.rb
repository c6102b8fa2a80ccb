# frozen_string_literal: true

require 'syskit/lsp/cursor'
require 'syskit/lsp/nesting'
require 'syskit/lsp/conf_sections'
require 'syskit/lsp/lookups'

module Syskit
  module LSP
    # What the cursor designates in the loaded app, found from the text at
    # the cursor (see Cursor) and the models, devices and definitions the
    # app recorded. Hover and Definition both start from it.
    #
    # +kind+ is one of :model (a data service, device, bus, composition,
    # task model or profile), :task_library, :device (a robot's device or
    # bus), :definition (a profile's), :deployment (a task library's),
    # :port (+owner+ is the child or model it is a port of) and :conf
    # (+object+ is the model whose configuration +name+ is chosen, see
    # ConfSections) and :namespace (a module of the app that holds models,
    # +Devices+ of Devices::GPS).
    Target = Struct.new(:kind, :object, :name, :owner)

    # Resolves a Cursor to a Target.
    class Resolver
      include Lookups

      # Statements whose string argument names the model they declare.
      DECLARATIONS = %w[data_service_type device_type com_bus_type profile].freeze

      attr_reader :app, :cursor

      def initialize(app, cursor)
        @app = app
        @cursor = cursor
      end

      # The Target at the cursor, nil when it is on nothing the app knows.
      def target
        from_string || from_orogen || from_constant || from_identifier
      end

      private

      def from_string
        str = cursor.string
        return unless str

        case str.call
        when 'using_task_library' then library(str.text)
        when 'through' then device_target(str.text)
        when 'device', 'com_bus' then device_target(str.text) if str.label == 'as'
        when 'with_conf' then conf_target(str.text)
        when *DECLARATIONS then declared_model(str.text)
        when 'define' then definition_target(str.text)
        when 'use_deployment', 'deployment' then deployment_target(str.text)
        else orogen_statement(str)
        end
      end

      # In an .orogen file: the task of +task_context 'Task'+, the model of
      # +task('name', 'lib::Task')+.
      def orogen_statement(str)
        name = case str.call
               when 'task_context' then "#{orogen_file_library&.name}::#{str.text}"
               when 'task' then str.text
               end
        model = name&.include?('::') && app.orogen.find_task_model(name)
        Target.new(:model, model, model.name) if model
      end

      # The loaded task library whose .orogen file is the cursor's.
      def orogen_file_library
        app.orogen.loaded_library_names.map { |n| app.orogen.library(n) }.find { |l| l.path == cursor.path }
      end

      def declared_model(name)
        found = profile_of(constant(name))
        Target.new(:model, found, name) if model?(found)
      end

      def library(name)
        Target.new(:task_library, app.orogen.library(name), name) if app.orogen.loaded?(name)
      end

      def device_target(name)
        found = device(name)
        Target.new(:device, found, name) if found
      end

      def conf_target(section)
        holder = statement_above
        model = conf_model(holder)
        Target.new(:conf, model, section, holder) if model
      end

      def deployment_target(name)
        found = app.orogen.find_deployment(name)
        Target.new(:deployment, found, name) if found
      end

      def definition_target(name)
        found = definition(name)
        Target.new(:definition, found, found.name) if found
      end

      def from_orogen
        chain = cursor.orogen_chain
        return unless chain

        lib = library(chain[0])
        return lib if chain.size == 1 || lib.nil?

        model = app.orogen.find_task_model("#{chain[0]}::#{chain[1]}")
        Target.new(:model, model, model.name) if model
      end

      def from_constant
        path = cursor.constant_path
        found = path && profile_of(constant(path))
        if model?(found)
          Target.new(:model, found, path)
        elsif found.is_a?(Module) && found.name
          Target.new(:namespace, found, found.name)
        end
      end

      # Whether +object+ is something the site has a kind of page for.
      def model?(object)
        object.is_a?(Models::DataServiceModel) || object.is_a?(Actions::Profile) ||
          (object.is_a?(Class) && object < AbstractComponent)
      end

      def from_identifier
        word = cursor.identifier
        case word
        when /\A(\w+)_dev\z/ then device_target(Regexp.last_match(1))
        when /\A(\w+)_def\z/ then definition_target(Regexp.last_match(1))
        when /\A(\w+)_port\z/ then port_target(Regexp.last_match(1))
        end
      end

      # A port of a composition's child (+follower_child.pose_port+), or
      # of the composition around the cursor.
      def port_target(name)
        return unless composition

        child_name = cursor.receiver&.delete_suffix('_child')
        owner = child_name && cursor.receiver.end_with?('_child') ? composition.find_child(child_name) : composition
        port = owner&.find_port(name)
        Target.new(:port, port, name, owner) if port
      end
    end
  end
end
