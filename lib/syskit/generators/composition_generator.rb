# frozen_string_literal: true

require 'syskit/generators/base'

module Syskit
  module Generators
    # `syskit gen cmp arm_control` (or control/arm): a composition in
    # models/compositions/ (AppName::Compositions::ArmControl), as
    # Syskit's generator makes one, and its test.
    class CompositionGenerator < Base
      attr_reader :name

      # +name+: path or constant form; +options+: force:, dry_run:.
      def initialize(root, name, **options)
        super(root, **options)
        @name = Name.parse(name, what: 'composition', acronyms: acronyms)
      end

      # Relative path => content of the files to write.
      def files
        locals = { name: name, modules: modules_for('Compositions', name),
                   require_path: "models/compositions/#{name.path}" }
        {
          name.model_path('compositions') => Template.render('composition', **locals),
          name.test_path('compositions') => Template.render('composition_test', **locals)
        }
      end
    end
  end
end
