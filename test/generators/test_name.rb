# frozen_string_literal: true

require 'helper'
require 'syskit/generators/name'
require 'syskit/generators/template'

module Syskit
  module Generators
    # Names given to generators (SPEC 10): path and constant forms, acronyms.
    class TestName < Minitest::Test
      def parse(text, acronyms: [])
        Name.parse(text, what: 'device', acronyms: acronyms)
      end

      def test_the_path_form_keeps_declared_acronyms
        name = parse('gps/ublox/f9', acronyms: %w[GPS CAN])
        assert_equal %w[GPS Ublox F9], name.constants
        assert_equal 'models/devices/gps/ublox/f9.rb', name.model_path('devices')
        assert_equal 'test/devices/gps/ublox/test_f9.rb', name.test_path('devices')
      end

      def test_the_path_form_is_plainly_camelized_without_acronyms
        assert_equal 'Gps::Ublox::F9', parse('gps/ublox/f9').to_s
      end

      def test_the_constant_form_is_kept_and_its_path_is_snake_case
        name = parse('GPS::Ublox::F9')
        assert_equal 'GPS::Ublox::F9', name.to_s
        assert_equal 'gps/ublox/f9', name.path
        assert_equal 'camera/gig_e', parse('Camera::GigE').path
      end

      def test_both_forms_of_a_name_land_in_the_same_file
        pairs = [%w[camera/gig_e Camera::GigE], %w[roboteq/can_open Roboteq::CANOpen], %w[imu_sensor IMUSensor]]
        pairs.each do |path, const|
          from_path = parse(path, acronyms: %w[CAN IMU])
          from_const = parse(const, acronyms: %w[CAN IMU])
          assert_equal const, from_path.to_s
          assert_equal path, from_const.path
        end
      end

      def test_under_adds_a_namespace_unless_the_name_starts_with_it
        assert_equal 'Bus::CAN', parse('can', acronyms: ['CAN']).under('Bus').to_s
        assert_equal 'Bus::CAN', parse('bus/can', acronyms: ['CAN']).under('Bus').to_s
        assert_equal 'Bus::CAN', parse('Bus::CAN').under('Bus').to_s
      end

      def test_names_that_make_no_constant_are_refused
        { '9lives' => /'9lives' does not make a Ruby constant name/,
          'foo-bar' => /'foo-bar' does not make/,
          'gps//f9' => /an empty part/,
          'gps/_f9' => /'_f9' does not make/,
          'GPS::Ublox/f9' => %r{'Ublox/f9' does not make},
          '' => /a device needs a name/ }.each do |text, message|
          error = assert_raises(GeneratorError, text) { parse(text) }
          assert_match message, error.message
          assert_match(%r{e\.g\. gps/ublox/f9}, error.hint)
        end
      end

      def test_absolute_paths_and_parent_directories_are_refused
        assert_match(/is an absolute path/, assert_raises(GeneratorError) { parse('/etc/passwd') }.message)
        assert_match(/is an absolute path/, assert_raises(GeneratorError) { parse('~/x') }.message)
        assert_match(/contains '\.\.'/, assert_raises(GeneratorError) { parse('gps/../../x') }.message)
      end

      def test_templates_indent_their_body_in_the_modules
        modules = Template::Modules.new(%w[A B])
        text = Template.indent_bodies("#{modules.open}\nx = 1\n\ny\n#{modules.close}\n", modules)
        assert_equal "module A\n  module B\n    x = 1\n\n    y\n  end\nend\n", text
      end
    end
  end
end
