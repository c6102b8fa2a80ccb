# frozen_string_literal: true

require 'syskit/robot/doc_comment'

module Syskit
  module Doc
    # One thing the site has a page for: a model, a task library or a
    # profile. +origin+ is the bundle it comes from when that is not the
    # app itself (nil for the app's own), +path+ its page, relative to the
    # site's root.
    Entry = Struct.new(:kind, :name, :object, :origin, :doc, :declared_at, :path) do
      # The first sentence of the documentation, for lists.
      def summary
        first = doc.to_s.split(/\n\s*\n/).first.to_s.gsub(/\s+/, ' ').strip
        first[/\A.*?[.!?](?=\s|\z)/] || first
      end
    end

    # What the site documents, kind by kind: everything the loaded app (and
    # the bundles it uses) defines. It only reads the app.
    #
    # Each kind is one row of KINDS: where its pages go, the template that
    # draws them, the view the template reads (nil: the object itself) and,
    # by its key, the +collect_KEY+ method that lists its objects. A new
    # kind of model is a row, a +collect_+ method (which can pick them
    # among #modules), a view and a template.
    class Catalog
      Kind = Struct.new(:key, :title, :singular, :dir, :template, :view)

      KINDS = [
        Kind.new(:device, 'Device models', 'device model', 'devices', 'model', :ModelView),
        Kind.new(:bus, 'Bus models', 'bus model', 'buses', 'model', :ModelView),
        Kind.new(:service, 'Data services', 'data service', 'services', 'model', :ModelView),
        Kind.new(:task_library, 'Task libraries', 'task library', 'libraries', 'task_library', nil),
        Kind.new(:task_model, 'Task models', 'task model', 'tasks', 'task_model', :TaskModelView),
        Kind.new(:composition, 'Compositions', 'composition', 'compositions', 'composition', :CompositionView),
        Kind.new(:profile, 'Profiles', 'profile', 'profiles', 'profile', :ProfileView)
      ].freeze

      attr_reader :app

      def initialize(app)
        @app = app
        @comments = Robot::DocComment.new
        @by_object = {}.compare_by_identity
        @entries = KINDS.to_h { |kind| [kind.key, collect(kind)] }
      end

      def kinds
        KINDS
      end

      # The entries of +kind+ (a key of KINDS), sorted by name.
      def entries(kind)
        @entries.fetch(kind)
      end

      def each_entry(&)
        @entries.each_value { |list| list.each(&) }
      end

      # The entry of a model, library or profile; nil when the site has no
      # page for it (a model of the gem itself, an anonymous one).
      def entry_for(object)
        @by_object[object]
      end

      # The bundle +path+ belongs to, by name; nil for the app's own files.
      def origin_of(path)
        return nil unless path

        bundle = app.bundles.find { |b| b.owns?(path) }
        return 'SYSKIT_OROGEN_PATH' unless bundle
        return nil if bundle.root == app.root

        bundle.equal?(App::BundleSearch::BUNDLED) ? "#{bundle.name} (syskit's own)" : bundle.name
      end

      private

      def collect(kind)
        send(:"collect_#{kind.key}").map do |name, object, doc, location, origin_path|
          slug = name.gsub('::', '.').gsub(/[^A-Za-z0-9_.-]/, '_')
          entry = Entry.new(kind, name, object, origin_of(origin_path || location&.path), doc, location,
                            "#{kind.dir}/#{slug}.html").freeze
          @by_object[object] = entry
        end.sort_by(&:name)
      end

      # Every named module and class reachable from the top-level modules
      # the app's files defined, in name order: where its models are.
      def modules
        @modules ||= begin
          seen = {}.compare_by_identity
          app.defined_modules.each { |mod| walk(mod, seen) }
          seen.keys.select(&:name)
        end
      end

      # Service, device and bus models; a bus's own services are
      # documented on its page.
      def models
        @models ||= modules.select { |m| m.is_a?(Models::DataServiceModel) && !m.bus_model }
      end

      def walk(mod, seen)
        return if seen[mod]

        seen[mod] = true
        mod.constants(false).sort.each do |const|
          next if mod.autoload?(const)

          value = constant(mod, const)
          walk(value, seen) if value.is_a?(Module)
        end
      end

      # The value of +mod+'s constant +name+; nil for one that is listed
      # but has none: an autoload whose file did not define it (Rock's
      # common_models has such backwards-compatibility names), once
      # something tried it, is listed and no longer an autoload.
      def constant(mod, name)
        mod.const_get(name, false)
      rescue NameError
        nil
      end

      def model_rows(klass, except = nil)
        models.select { |m| m.instance_of?(klass) || (m.is_a?(klass) && !(except && m.is_a?(except))) }
              .map { |m| [m.name, m, model_doc(m), m.declared_at] }
      end

      def collect_device
        model_rows(Models::DeviceModel, Models::ComBusModel)
      end

      def collect_bus
        model_rows(Models::ComBusModel)
      end

      def collect_service
        model_rows(Models::DataServiceModel, Models::DeviceModel)
      end

      def collect_task_library
        app.orogen.loaded_library_names.map do |name|
          library = app.orogen.library(name)
          location = Location.new(library.path, 0)
          [name, library, nil, location]
        end
      end

      def collect_task_model
        app.orogen.each_task_model.map do |model|
          spec = model.spec
          [model.name, model, spec.doc || @comments.above(spec.declared_at), spec.declared_at, spec.library.path]
        end
      end

      # Composition models (not the submodels specializations make).
      def collect_composition
        modules.select { |m| m.is_a?(Class) && m < Composition && !m.specialization? }
               .map { |m| [m.name, m, m.doc, m.declared_at] }
      end

      def collect_profile
        app.profiles.values.select(&:name).map do |profile|
          [profile.name, profile, @comments.above(profile.declared_at), profile.declared_at]
        end
      end

      def model_doc(model)
        model.doc || @comments.above(model.declared_at)
      end
    end
  end
end
