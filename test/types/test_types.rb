# frozen_string_literal: true

require 'helper'

module Syskit
  # Types declared in Ruby typekits, as configure code uses them (SPEC 2).
  class TestTypes < Minitest::Test
    TYPEKIT = <<~RUBY
      struct 'Device' do
        field 'name', '/std/string'
        field 'id', '/uint32_t'
        field 'mask', '/uint32_t'
      end
      enum 'Mode', %w[ACTIVE PASSIVE]
      opaque 'Calibration'
      struct 'Stamp' do
        field 'usec', '/int64_t'
      end
      convert_from_ruby ::Time, 'Stamp' do |time|
        new(usec: time.tv_sec * 1_000_000 + time.tv_usec)
      end
      struct 'Reading' do
        field 'stamp', '/my_bus/Stamp'
      end
    RUBY

    def setup
      root = my_app(nil, 'models/typekits/my_bus.rb' => TYPEKIT,
                         'models/devices/x.rb' => "module MyApp\n  import_types_from 'my_bus'\nend\n")
      @app = load_app(root)
    end

    def test_names_and_objects_resolve_to_the_same_type
      assert_same ::Types.my_bus.Device, @app.types.find('/my_bus/Device')
      assert_same ::Types.canbus.Message, @app.types.find('canbus/Message')
      assert_same @app.types.find('/int32_t'), @app.types.find('int')
      assert_equal '/std/vector</my_bus/Device>', @app.types.find('/std/vector< /my_bus/Device >').name
    end

    def test_struct_values_are_built_positionally_or_with_keywords
      device = ::Types.my_bus.Device.new('gps', 1, 2)
      assert_equal device, ::Types.my_bus.Device.new(name: 'gps', id: 1, mask: 2)
      assert_equal ::Types.my_bus.Device.new('gps', 1), ::Types.my_bus.Device.new(name: 'gps', id: 1, mask: 0)
      assert_equal %w[gps 1 2], [device.name, device.id.to_s, device.mask.to_s]
      device.mask = 3
      assert_equal({ 'name' => 'gps', 'id' => 1, 'mask' => 3 }, ::Types.my_bus.Device.to_plain(device))
      refute_equal device, ::Types.my_bus.Device.new('gps', 1, 2)
    end

    def test_struct_values_check_their_fields
      error = assert_raises(ArgumentError) { ::Types.my_bus.Device.new('gps', -1) }
      assert_match(%r{/my_bus/Device.id: -1 is out of range for /uint32_t}, error.message)
      error = assert_raises(ArgumentError) { ::Types.my_bus.Device.new(nmae: 'gps') }
      assert_match(/has no field 'nmae' \(did you mean 'name'\?\)/, error.message)
      error = assert_raises(ArgumentError) { ::Types.my_bus.Device.new('a', 1, 2, 3) }
      assert_match(/has 3 fields \(name, id, mask\), got 4 values/, error.message)
    end

    # Typelib's convert_from_ruby: a Ruby value stands for the type's.
    def test_a_typekit_converts_ruby_values
      reading = ::Types.my_bus.Reading.new(stamp: Time.at(2, 500_000))
      assert_equal 2_500_000, reading.stamp.usec
      reading.stamp = Time.at(3)
      assert_equal ::Types.my_bus.Stamp.new(3_000_000), reading.stamp
      error = assert_raises(ArgumentError) { reading.stamp = 'now' }
      assert_match(%r{/my_bus/Reading.stamp: expected a /my_bus/Stamp or a hash of its fields \(usec\)}, error.message)
    end

    def test_a_conversion_to_a_type_that_is_not_a_struct_is_refused
      @app.unload
      typekit = "enum 'Mode', %w[ACTIVE PASSIVE]\nconvert_from_ruby ::Symbol, 'Mode' do |s| s end\n"
      root = my_app(nil, 'models/typekits/modes.rb' => typekit,
                         'models/devices/x.rb' => "module MyApp\n  import_types_from 'modes'\nend\n")
      app = load_app(root, problems: true)
      assert_reported app.errors.first, %r{convert_from_ruby applies to struct types; /modes/Mode is not one},
                      at: 'models/typekits/modes.rb:2', hint: /struct 'Mode'/, root: root
    end

    # Rock's base typekit: a Ruby Time is a /base/Time, and base/float's
    # Base comes with the typekit, as Rock's Ruby plugin of it loads it.
    def test_the_base_typekit_takes_ruby_times_and_brings_base
      @app.unload
      refute Object.const_defined?(:Base, false)
      app = load_app(my_app(nil, 'models/devices/x.rb' => "module MyApp\n  import_types_from 'base'\nend\n"))
      temperature = ::Types.base.samples.Temperature.new(time: Time.at(1, 250))
      assert_equal 1_000_250, temperature.time.microseconds
      assert Base.unknown.nan?
      app.unload
      refute Object.const_defined?(:Base, false), 'Base goes with the app'
    end

    def test_plain_data_converts_to_values
      type = @app.types.find('/std/vector</my_bus/Device>')
      values = type.from_ruby([{ 'name' => 'a', 'id' => 1 }, ::Types.my_bus.Device.new('b')])
      assert_equal [::Types.my_bus.Device.new('a', 1, 0), ::Types.my_bus.Device.new('b', 0, 0)], values
    end

    def test_enums_opaque_types_and_arrays
      assert_equal :PASSIVE, ::Types.my_bus.Mode.from_ruby('PASSIVE')
      assert_raises(Types::ValueError) { ::Types.my_bus.Mode.from_ruby('SLEEP') }
      assert_equal({ 'k' => [1, 'x'] }, ::Types.my_bus.Calibration.from_ruby({ 'k' => [1, 'x'] }))
      assert_equal [0] * 8, @app.types.find('/uint8_t[8]').zero
    end

    # A plan is written as JSON: values it cannot hold are refused by the
    # types, wherever they are set (configuration files, configure, struct
    # fields, defaults, opaque data at any depth).
    # NaN and the infinities are doubles, as in Typelib (Rock's
    # configuration files write .nan).
    def test_non_finite_doubles_are_values
      double = @app.types.find('/double')
      assert double.from_ruby(Float::NAN).nan?
      assert_equal [Float::INFINITY, -Float::INFINITY], [double.from_ruby(1.0 / 0), double.from_ruby(-1.0 / 0)]
      assert_equal Float::INFINITY, double.from_ruby(10**400)
    end

    def test_values_a_plan_cannot_hold_are_refused
      refused = {
        @app.types.find('/double') => ['1.5', Complex(1, 1)],
        @app.types.find('/std/string') => ["\xFF", "\xC0\xA8".b, "caf\xE9".dup.force_encoding('UTF-8')],
        ::Types.my_bus.Calibration => [{ "\xFF".b => 1 }, [:ok, ["\xFF"]]],
        ::Types.my_bus.Mode => ["\xFF"]
      }
      refused.each do |type, values|
        values.each { |v| assert_raises(Types::ValueError, "#{type}: #{v.inspect}") { type.from_ruby(v) } }
      end
      error = assert_raises(ArgumentError) { ::Types.my_bus.Device.new("gps\xFF") }
      assert_match(%r{/my_bus/Device.name: expected UTF-8 text for /std/string, got bytes that are not valid UTF-8},
                   error.message)
    end

    def test_text_in_other_encodings_is_converted_to_utf8
      string = @app.types.find('/std/string')
      converted = string.from_ruby("caf\xE9".dup.force_encoding('ISO-8859-1'))
      assert_equal 'café', converted
      assert_equal Encoding::UTF_8, converted.encoding
      assert_equal Encoding::UTF_8, string.from_ruby('plain'.b).encoding
      assert_equal 'café', string.from_ruby('café'.b)
      assert_equal 2.0, @app.types.find('/double').from_ruby(2)
    end
  end
end
