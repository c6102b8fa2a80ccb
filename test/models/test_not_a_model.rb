# frozen_string_literal: true

require 'helper'

module Syskit
  # driver_for and provides given something that is not a model: the hint
  # says what was given instead (nil from a constant, a model's name).
  class TestNotAModel < Minitest::Test
    def problem(statement)
      root = my_app(nil, 'models/orogen/imu.rb' => "Syskit.extend_model(OroGen.imu.Task) do\n  #{statement}\nend\n")
      [load_problem(root, everything: true), root]
    end

    def test_a_name_instead_of_the_model
      error, root = problem("driver_for 'MyApp::Devices::IMU'")
      assert_reported error, /driver_for expects a device or bus model, got "MyApp::Devices::IMU"/,
                      at: 'models/orogen/imu.rb:2', hint: /not its name: driver_for MyApp::Devices::IMU\z/, root: root
    end

    def test_nil
      error, root = problem("provides nil, as: 'pose'")
      assert_reported error, /provides expects a data service model, got nil/,
                      at: 'models/orogen/imu.rb:2', hint: /\Athe model given is nil here: require the file/, root: root
    end
  end
end
