# frozen_string_literal: true

require 'helper'

module Syskit
  # The models the gem ships (CommonModels' CAN bus, the canbus library,
  # a few typekits) are the models/ directory at the top of the gem, a
  # bundle of their own: the rest of the gem (its lib/ above all) is never
  # an app's code, a file `require` finds for an app, or a user's frame.
  class TestBundledModels < Minitest::Test
    MODELS = File.join(GEM_ROOT, 'models')

    def test_the_bundled_models_are_the_top_level_models_directory
      assert_equal [MODELS], App::BundleSearch::BUNDLED.owned_dirs
      refute File.exist?(File.join(GEM_ROOT, 'bundles')), 'the bundled models moved back under bundles/'
      app = load_app(write_app({}))
      assert_equal File.join(MODELS, 'devices', 'bus', 'can.rb'),
                   CommonModels::Devices::Bus::CAN.declared_at.path
      assert_equal File.join(MODELS, 'orogen', 'canbus.orogen'), app.using_task_library('canbus').path
      assert_equal File.join(MODELS, 'typekits'), app.typekit_search_dirs.last
    end

    def test_the_bundled_files_are_required_under_common_models_names
      app = load_app(write_app({}))
      can = File.join(MODELS, 'devices', 'bus', 'can.rb')
      %w[common_models/models/devices/bus/can models/devices/bus/can devices/bus/can].each do |name|
        assert_equal can, app.required_file(name), name
      end
      assert app.environment_file?(can)
    end

    # Rock's logger as its current oroGen spec declares it: what Rock's
    # common_models sets in the logger's update_properties exists.
    def test_the_logger_has_rock_s_file_handling_properties
      files = { 'models/orogen/logs.rb' => <<~RUBY,
        Syskit.extend_model OroGen.logger.Logger do
          def update_properties
            super
            properties.overwrite_existing_files = true
          end
        end
      RUBY
                'config/robots/default.rb' => "using_task_library 'logger'\n" }
      load_app(write_app(files))
      props = OroGen.logger.Logger.spec.all_properties
      assert_equal({ 'file' => '', 'overwrite_existing_files' => false, 'auto_timestamp_files' => false },
                   props.transform_values(&:initial_value))
      task = OroGen.logger.Logger.new
      task.update_properties
      assert task.properties['overwrite_existing_files']
    end

    def test_the_gem_s_library_is_not_app_code
      app = load_app(write_app({}))
      dsl = File.join(GEM_ROOT, 'lib', 'syskit', 'dsl.rb')
      refute app.environment_file?(dsl)
      refute app.environment_file?(File.join(GEM_ROOT, 'test', 'helper.rb'))
      assert_nil app.required_file('syskit/dsl')
      assert_nil app.required_file('common_models/lib/syskit/dsl')
      assert_nil app.required_file('models/../lib/syskit/dsl')
      refute_includes $LOAD_PATH, GEM_ROOT
      refute_includes $LOAD_PATH, File.dirname(GEM_ROOT)
      app.unload
      assert_includes $LOADED_FEATURES, dsl, 'unloading an app unloaded the gem itself'
    end

    # The gem's directory is not an app, although it has a models/
    # directory: --app names it as such, and commands run in it say they
    # are not in an app.
    def test_the_gem_itself_is_not_an_app
      refute App.root?(GEM_ROOT)
      found = App.find_root(File.join(MODELS, 'devices', 'bus'))
      refute found&.start_with?(GEM_ROOT), "#{found} is taken for an app"
      out, err, status = run_cli('check', '--app', GEM_ROOT)
      assert_equal [1, ''], [status, out]
      assert_match(/\A'#{Regexp.escape(GEM_ROOT)}' is not an app: it is the syskit gem itself /, err)
      out, err, status = run_cli('check', chdir: MODELS)
      assert_equal [1, ''], [status, out]
      assert_match(/\A#{Regexp.escape(MODELS)} is not in a Syskit app\n/, err)
    end

    # Naming the gem as a bundle gives its models/, not the whole gem.
    def test_the_gem_named_as_a_bundle_is_its_models_only
      root = write_app({ 'config/syskit.yml' => "bundles: [#{GEM_ROOT}/]\n" })
      app = load_app(root)
      assert_equal [root, GEM_ROOT], app.bundle_roots
      assert_same App::BundleSearch::BUNDLED, app.bundles.last
      refute app.environment_file?(File.join(GEM_ROOT, 'lib', 'syskit.rb'))
    end

    # An error of the user's code, raised in the gem's library or in a
    # bundled model's method, is located in the user's file.
    def test_errors_through_the_gem_are_located_in_the_user_s_file
      root = write_app({ 'models/devices/thing.rb' => "device_type 'Thing'\n",
                         'models/profiles/base.rb' => <<~RUBY })
                           profile 'Base' do
                             robot do
                               can = com_bus(CommonModels::Devices::Bus::CAN, as: 'can0')
                               can.device(Devices::Thing, as: 'dev').can_id('x', 3)
                             end
                           end
                         RUBY
      app = load_app(root, problems: true)
      error = app.errors.find { |e| e.message.include?('can_id') }
      assert error, app.errors.map(&:message).join("\n")
      assert_equal Location.new(File.join(root, 'models', 'profiles', 'base.rb'), 4), error.location
    end
  end
end
