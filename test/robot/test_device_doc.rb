# frozen_string_literal: true

require 'helper'

module Syskit
  # A device's documentation, as Syskit's device tests describe it: doc(x)
  # keeps x.to_str, doc(nil) removes it, device(..., doc: '...') sets it,
  # and the comment block just above a device statement becomes it.
  class TestDeviceDoc < Minitest::Test
    def robot(source)
      root = my_app(source)
      load_app(root)
      MyApp::Profiles::Base.syskit_profile.robot
    end

    # Anything with to_str, as Syskit accepts.
    class Text
      def to_str
        'the IMU under the seat'
      end
    end

    def test_doc_keeps_the_string_of_what_it_is_given_and_nil_removes_it
      imu = robot("device(Devices::IMU, as: 'imu')\n").find_device('imu')
      assert_nil imu.doc
      assert_same imu, imu.doc(Text.new)
      assert_equal 'the IMU under the seat', imu.doc
      assert_same imu, imu.doc(nil)
      assert_nil imu.doc
    end

    def test_doc_refuses_what_is_not_a_string
      root = my_app("device(Devices::IMU, as: 'imu').doc(42)\n")
      assert_reported load_problem(root), /invalid doc 42 for device 'imu'/,
                      at: 'models/profiles/base.rb:9', hint: /doc takes a string, or nil/, root: root
    end

    def test_doc_option_of_device_and_com_bus
      robot = robot(<<~RUBY)
        device(Devices::IMU, as: 'imu', doc: 'the main IMU')
        com_bus(CommonModels::Devices::Bus::CAN, as: 'can0', doc: 'the engine bus')
      RUBY
      assert_equal 'the main IMU', robot.find_device('imu').doc
      assert_equal 'the engine bus', robot.find_device('can0').doc
    end

    def test_the_comment_block_above_a_device_statement_becomes_its_doc
      robot = robot(<<~RUBY)
        # The IMU under the seat.
        #
        #   mounted upside down
        device(Devices::IMU, as: 'imu')

        # Not this one: a blank line separates it from the statement

        device(Devices::IMU, as: 'spare')
        com_bus CommonModels::Devices::Bus::CAN, as: 'can0'
        through 'can0' do
          # The water temperature,
          # read every second
          device(Devices::TemperatureSensor, as: 'water')
        end
      RUBY
      assert_equal "The IMU under the seat.\n\n  mounted upside down", robot.find_device('imu').doc
      assert_nil robot.find_device('spare').doc
      assert_equal "The water temperature,\nread every second", robot.find_device('water').doc
    end

    def test_a_comment_keeps_its_characters
      robot = robot("#!not a comment\n#   Caméra avant, 20 images/s\ndevice(Devices::IMU, as: 'imu')\n")
      doc = robot.find_device('imu').doc
      assert_equal 'Caméra avant, 20 images/s', doc
      assert_equal Encoding::UTF_8, doc.encoding
    end

    def test_the_doc_option_wins_over_the_comment
      robot = robot("# from the comment\ndevice(Devices::IMU, as: 'imu', doc: 'from the option')\n")
      assert_equal 'from the option', robot.find_device('imu').doc
    end
  end
end
