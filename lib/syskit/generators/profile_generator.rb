# frozen_string_literal: true

require 'syskit/generators/base'

module Syskit
  module Generators
    # `syskit gen profile live/base`: a profile with an empty robot block in
    # models/profiles/ (AppName::Profiles::Live::Base) and its test.
    class ProfileGenerator < Base
      attr_reader :name

      # +name+: path or constant form; +options+: force:, dry_run:.
      def initialize(root, name, **options)
        super(root, **options)
        @name = Name.parse(name, what: 'profile', acronyms: acronyms)
      end

      # Relative path => content of the files to write.
      def files
        self.class.files(app_name, name)
      end

      # The files of profile +name+ in app +app_name+ (also used by gen app).
      def self.files(app_name, name)
        locals = { name: name, modules: modules_for(app_name, 'Profiles', name) }
        {
          name.model_path('profiles') => Template.render('profile', **locals),
          name.test_path('profiles') => Template.render('profile_test', **locals)
        }
      end
    end
  end
end
