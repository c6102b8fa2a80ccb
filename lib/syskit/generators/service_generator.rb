# frozen_string_literal: true

require 'syskit/generators/base'

module Syskit
  module Generators
    # `syskit gen srv pose` (or sensing/pose): a data service in
    # models/services/ (AppName::Services::Pose), which device models and
    # drivers provide, and its test.
    class ServiceGenerator < Base
      attr_reader :name

      # +name+: path or constant form; +options+: force:, dry_run:.
      def initialize(root, name, **options)
        super(root, **options)
        @name = Name.parse(name, what: 'data service', acronyms: acronyms)
      end

      # Relative path => content of the files to write.
      def files
        locals = {
          name: name, modules: modules_for('Services', name), full_name: "#{app_name}::Services::#{name}",
          require_path: "models/services/#{name.path}", port_name: name.path_segments.last
        }
        {
          name.model_path('services') => Template.render('service', **locals),
          name.test_path('services') => Template.render('service_test', **locals)
        }
      end
    end
  end
end
