# frozen_string_literal: true

require 'helper'
require 'json'
require 'open3'

module Syskit
  # The plan as text, JSON and DOT (SPEC 9).
  class TestRender < Minitest::Test
    EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')

    def example_plan
      app = load_app(EXAMPLE)
      Network::Generator.plan_profile(app, AwesomeRobot::Profiles::Live::Base.syskit_profile).plan
    end

    # Rock's configuration files write .nan for an unknown value; a
    # configure method may compute an infinity: both are values of a
    # double, written in the JSON as typelib's to_simple_value writes
    # them ("NaN", "Infinity", "-Infinity"), so that strict parsers read
    # the plan.
    NAN_SPEC = <<~RUBY
      name 'imu'
      import_types_from 'base'
      task_context 'Task' do
        property 'rate', 'int', 100
        property 'bias', 'double', 0.0
        property 'limit', 'double', 0.0
        property 'lowest', 'double', 0.0
        output_port 'samples', '/base/samples/IMUSensors'
      end
    RUBY
    NAN_EXTENSION = <<~RUBY
      require 'models/devices/imu'
      Syskit.extend_model OroGen.imu.Task do
        driver_for MyApp::Devices::IMU, as: 'imu'
        def configure
          super
          properties.limit = 1.0 / 0
          properties.lowest = -1.0 / 0
        end
      end
    RUBY

    def nan_app
      my_app("device(Devices::IMU, as: 'imu')\n",
             'config/orogen/imu::Task.yml' => "--- name:default\nrate: 50\nbias: .nan\n",
             'models/orogen/imu.orogen' => NAN_SPEC, 'models/orogen/imu.rb' => NAN_EXTENSION)
    end

    def test_nan_and_infinity_are_values_of_doubles
      root = nan_app
      out, err, status = run_cli('plan', '--app', root, '--format', 'json')
      assert_equal 0, status, err
      properties = JSON.parse(out)['tasks'].first['properties']
      assert_equal({ 'bias' => 'NaN', 'limit' => 'Infinity', 'lowest' => '-Infinity' },
                   properties.slice('bias', 'limit', 'lowest'))
      text, = run_cli('plan', '--app', root)
      assert_match(/bias: NaN\n\s+limit: Infinity\n\s+lowest: -Infinity\n/, text)
    end

    # A plan file of an older version wrote NaN bare: it is still read, and
    # its NaN is the same value as the string "NaN". The diff in JSON is
    # strict JSON too.
    def test_diff_of_plans_holding_nan
      root = nan_app
      out, = run_cli('plan', '--app', root, '--format', 'json')
      old = File.join(root, 'old.json')
      File.write(old, out.sub('"NaN"', 'NaN').sub('"-Infinity"', '-Infinity'))
      diff, err, status = run_cli('plan', '--app', root, '--diff', old)
      assert_equal [0, "the plans are the same\n"], [status, diff.lines.last], err
      File.write(File.join(root, 'config/orogen/imu::Task.yml'), "--- name:default\nrate: 50\nbias: 0.5\n")
      diff, err, status = run_cli('plan', '--app', root, '--diff', old, '--format', 'json')
      assert_equal 0, status, err
      change = JSON.parse(diff)['lists']['tasks']['changed'].first['changes'].first
      assert_equal({ 'path' => %w[properties bias], 'old' => 'NaN', 'new' => 0.5 }, change)
    end

    # Every JSON output of the gem goes through Render::JSON.pretty.
    def test_json_documents_are_strict_json_with_special_floats
      data = { 'a' => [1.5, Float::NAN, { 'b' => -Float::INFINITY }], 'c' => Float::INFINITY, 'd' => 'NaN' }
      text = Render::JSON.pretty(data)
      assert_equal({ 'a' => [1.5, 'NaN', { 'b' => '-Infinity' }], 'c' => 'Infinity', 'd' => 'NaN' }, JSON.parse(text))
      assert_equal "#{JSON.pretty_generate('a' => [1, 2])}\n", Render::JSON.pretty('a' => [1, 2])
    end

    def test_json_has_the_keys_of_the_spec
      doc = JSON.parse(Render::JSON.render(example_plan))
      assert_equal %w[profile robot tasks devices connections order buses compositions], doc.keys
      assert_equal 'AwesomeRobot::Profiles::Live::Base', doc['profile']
      assert_equal 'default', doc['robot']
      can0 = doc['tasks'].find { |t| t['name'] == 'can0' }
      assert_equal %w[name model deployment devices conf properties ports depends_on unmanaged operations], can0.keys
      assert_equal false, can0['unmanaged']
      assert_equal ['canbus::Task', 'can0', ['can0'], ['default']],
                   can0.values_at('model', 'deployment', 'devices', 'conf')
      assert_includes can0['ports'], { 'name' => 'temperature_sensor', 'direction' => 'output',
                                       'type' => '/canbus/Message', 'dynamic' => true }
      assert_includes doc['connections'], { 'from' => { 'task' => 'can0', 'port' => 'temperature_sensor' },
                                            'to' => { 'task' => 'temperature_sensor', 'port' => 'can_in' },
                                            'type' => '/canbus/Message',
                                            'policy' => { 'type' => 'buffer', 'size' => 2 } }
      assert_equal({ 'step' => 'configure', 'task' => 'aft_camera' }, doc['order'].first)
    end

    # Lists are written by the json library a slice at a time; the document
    # is still the one it makes of the whole plan.
    def test_json_is_the_pretty_json_of_the_plan
      [example_plan, long_plan, long_plan(profile: nil, steps: 0)].each do |plan|
        assert_equal "#{JSON.pretty_generate(plan.to_h)}\n", Render::JSON.render(plan)
      end
    end

    # Renderers hand their output to the IO a chunk at a time (a 10,000
    # device plan is 16 MB of JSON), and write the bytes render returns.
    def test_renderers_write_in_chunks
      plan = long_plan(steps: 20_000)
      [Render::JSON, Render::Text, Render::Dot].each do |renderer|
        io = ChunkRecorder.new
        assert_same io, renderer.write(plan, io)
        assert_operator io.chunks.size, :>, 2, renderer
        assert_operator io.chunks.map(&:bytesize).max, :<, 2 * Render::Output::CHUNK, renderer
        assert_equal renderer.render(plan), io.chunks.join, renderer
      end
    end

    # Records what is written, copying it: renderers reuse their buffer.
    class ChunkRecorder
      attr_reader :chunks

      def initialize
        @chunks = []
      end

      def write(data)
        @chunks << data.dup
        data.bytesize
      end
    end

    # A plan whose order has +steps+ steps (more than a JSON slice).
    def long_plan(profile: 'P', steps: 600)
      order = Array.new(steps) { |i| Network::Plan::Step.new(i.even? ? 'configure' : 'start', "task#{i / 2}") }
      connections = Array.new(steps / 2) do |i|
        Network::Plan::Connection.new(Network::Plan::Endpoint.new("bus#{i % 3}", "dev#{i}"),
                                      Network::Plan::Endpoint.new("dev#{i}", 'can_in'), '/canbus/Message',
                                      { 'type' => 'buffer', 'size' => 20 })
      end
      Network::Plan.new(profile: profile, robot: 'default', tasks: [], devices: [], connections: connections,
                        order: order)
    end

    def test_generating_twice_gives_byte_identical_json
      first, = run_cli('plan', '--app', EXAMPLE, '--format', 'json')
      second, = run_cli('plan', '--app', EXAMPLE, '--format', 'json')
      refute_empty first
      assert_equal first, second
    end

    def test_the_plan_is_a_frozen_value
      plan = example_plan
      assert plan.frozen?
      assert plan.tasks.first.frozen?
      assert plan.tasks.first.properties.frozen?
      assert_raises(FrozenError) { plan.tasks << nil }
    end

    def test_dot_draws_tasks_as_records_of_their_ports_connected_port_to_port
      dot = Render::Dot.render(example_plan)
      title = %(  label="AwesomeRobot::Profiles::Live::Base on robot 'default'";\n  labelloc=t;)
      assert dot.start_with?(%(digraph "AwesomeRobot::Profiles::Live::Base" {\n#{title}))
      # Inputs on the left, the task in the middle, outputs on the right.
      # Under the model, the device's CAN filter.
      assert_includes dot, '"temperature_sensor" [label="{{<i0> can_in}|' \
                           'temperature_sensor\\ncan_temperature_sensor::Task\\nid\\ 0x1234/0xFFFF|' \
                           '{<o0> can_out|<o1> temperature}}"'
      assert_includes dot, '"can0":o1 -> "temperature_sensor":i0 [label="buffer 2"];'
    end

    # A device's frames to its bus's driver are written from the driver,
    # the arrow turned back: graphviz then ranks the device after the
    # driver, as the driver's writes to it do, instead of looping it round
    # the driver; each carries its own policy.
    def test_dot_draws_the_frames_into_a_bus_driver_turned_back_each_labelled
      dot = Render::Dot.render(example_plan)
      assert_includes dot, %(  "can0":i0 -> "sync":o0 [dir=back, label="buffer 12"];\n)
      assert_includes dot, %(  "can0":i0 -> "temperature_sensor":o0 [dir=back, label="buffer 2"];\n)
      into_can1 = dot.lines.grep(/^  "can1":i0 -> /)
      assert_equal [%(  "can1":i0 -> "left_motor":o0 [dir=back, label="buffer 20"];\n),
                    %(  "can1":i0 -> "right_motor":o0 [dir=back, label="buffer 20"];\n)], into_can1
      refute_match(/-> "can[01]":/, dot)
      # The bus driver's writes to a bus attached through it go forward.
      assert_includes dot, %(  "can0":o0 -> "n2k":i0 [label="buffer 20"];\n)
    end

    def test_dot_draws_the_ports_the_plan_connects_and_counts_the_others
      plan = example_plan
      dot = Render::Dot.render(plan)
      gps = plan.tasks.find { |task| task.name == 'gps' }
      hidden = gps.ports.count { |port| port.name != 'pose_samples' }
      assert_operator hidden, :>, 1
      note = "+#{hidden}\\ ports\\ not\\ connected"
      assert_includes dot, %("gps" [label="{gps\\ngps_ublox::F9Task\\n#{note}|{<o0> pose_samples}}")
      all = Render::Dot.write(plan, StringIO.new(+''), all_ports: true).string
      refute_includes all, 'not\\ connected'
      gps_node = all[/^    "gps" \[label=.*$/]
      gps.ports.each { |port| assert_match(/<[io]\d+> #{port.name}[|}]/, gps_node) }
    end

    def test_dot_labels_a_bus_with_its_bitrate_and_load
      dot = Render::Dot.render(example_plan)
      assert_match(%r{^  subgraph "cluster_bus_can1" \{\n    label="bus can1\\n1 Mbit/s, load \d+\.\d %";}, dot)
      # A bus without a bitrate has no load to show.
      assert_includes dot, %(label="bus n2k"; )
    end

    def test_dot_writes_a_policy_once_for_the_connections_into_one_port
      dot = Render::Dot.render(example_plan)
      into_monitor = dot.lines.grep(/-> "temperature_monitor":i0/)
      assert_equal [%(  "temperature_sensor":o1 -> "temperature_monitor":i0 [label="data"];\n),
                    %(  "water_temperature":o0 -> "temperature_monitor":i0;\n)], into_monitor
    end

    # Ranks closer than graphviz's default and boxes titled smaller than
    # the plan keep the example app's plan within a 1,400 px window.
    def test_dot_spaces_its_ranks_and_titles_its_boxes_to_fit_a_window
      dot = Render::Dot.render(example_plan)
      assert_includes dot, "  rankdir=LR;\n  ranksep=0.3;\n  node ["
      boxes = dot.lines.grep(/^\s+subgraph /).size
      assert_equal 7, boxes
      assert_equal boxes, dot.lines.grep(/^\s+label=".*"; .*; fontsize=12;$/).size
    end

    # A specialization's name (model/selection) is the widest line of its
    # box's title: the selection goes on a line of its own.
    def test_dot_titles_a_specialized_composition_on_two_lines
      app = load_app(File.join(GEM_ROOT, 'examples', 'arm_lab'))
      bench = app.profiles.fetch('ArmLab::Profiles::Bench')
      plan = Network::Generator.plan_profile(app, bench, actions: ['reach_target_def']).plan
      assert_includes Render::Dot.render(plan),
                      'label="reach_target.control\\nArmLab::Compositions::ArmControl\\n/controller.is_a?(arm_control::'
    end

    def test_svg_of_the_example_fits_a_1400_px_window
      skip 'graphviz (dot) is not installed' unless system('command -v dot >/dev/null 2>&1')

      svg = Render::Svg.write(example_plan, StringIO.new(+'')).string
      width = Float(svg[/<svg width="([\d.]+)pt"/, 1])
      # 1,400 px less a scroll bar, at 96 px to 72 pt.
      assert_operator width * 96 / 72, :<=, 1385, "the plan is #{width} pt wide"
    end

    def test_dot_groups_the_devices_of_a_bus_with_its_driver_and_draws_bus_drivers_apart
      dot = Render::Dot.render(example_plan)
      can0 = dot[/^  subgraph "cluster_bus_can0" \{\n.*?^  \}\n/m]
      refute_nil can0
      %w[can0 sync].each { |task| assert_match(/^    "#{task}" \[/, can0) }
      # n2k is attached through can0, and fuel_level through n2k.
      assert_match(/^    subgraph "cluster_bus_n2k" \{\n.*^      "fuel_level" \[.*^      "n2k" \[/m, can0)
      assert_match(/^    "can0" \[label=.*style="filled,bold"/, can0)
      assert_match(/^    "sync" \[label=.*style=filled, fillcolor="#ffffff"\];$/, can0)
      # A deployment of several tasks is a box, one of a single task none.
      assert_match(/^    subgraph "cluster_deployment_motors" \{\n.*"left_motor".*"right_motor"/m, dot)
      refute_match(/cluster_deployment_(gps|can0|sync)"/, dot)
    end

    # A device's driver that a composition uses is drawn with the
    # composition's other children, not in its bus's box: its connections
    # to the bus's driver say which bus it is on.
    def test_dot_draws_a_composition_around_the_children_it_alone_has_devices_included
      dot = Render::Dot.render(example_plan)
      drive = dot[/^  subgraph "cluster_composition_drive" \{\n.*?^  \}\n/m]
      %w[gps path_follower].each { |task| assert_match(/^    "#{task}" \[/, drive) }
      motors = /^    subgraph "cluster_deployment_motors" \{\n.*^      "left_motor" \[.*^      "right_motor" \[/m
      assert_match(motors, drive)
      watch = dot[/^  subgraph "cluster_composition_watch_temperatures" \{\n.*?^  \}\n/m]
      %w[temperature_monitor temperature_sensor water_temperature].each do |task|
        assert_match(/^    "#{task}" \[/, watch)
      end
      # Its bus's box keeps the bus's driver and the devices no composition
      # uses.
      can1 = dot[/^  subgraph "cluster_bus_can1" \{\n.*?^  \}\n/m]
      assert_equal %w[can1], can1.scan(/^\s+"(\w+)" \[/).flatten
      can0 = dot[/^  subgraph "cluster_bus_can0" \{\n.*?^  \}\n/m]
      assert_equal %w[can0 sync fuel_level n2k], can0.scan(/^\s+"(\w+)" \[/).flatten
    end

    def test_dot_links_tasks_to_the_urls_given_for_their_models
      plan = example_plan
      dot = Render::Dot.write(plan, StringIO.new(+''), links: { 'canbus::Task' => 'tasks/canbus "x".html' }).string
      assert_match(%r{^    "can0" \[label=.*fillcolor="#cfe0f5", color="#2f5d95", URL="tasks/canbus \\"x\\".html", (?#
                   )tooltip="canbus::Task"\];$}, dot)
      refute_match(/^    "sync" \[.*URL=/, dot)
      refute_includes Render::Dot.render(plan), 'URL='
    end

    def test_dot_is_accepted_by_graphviz
      skip 'graphviz (dot) is not installed' unless system('command -v dot >/dev/null 2>&1')

      out, err, status = run_cli('plan', '--app', EXAMPLE, '--format', 'svg')
      assert_equal [0, ''], [status, err]
      svg, err, status = Open3.capture3('dot', '-Tsvg', stdin_data: Render::Dot.render(example_plan))
      assert status.success?, err
      assert_match(/<svg/, svg)
      assert_equal svg, out
    end

    def test_svg_when_dot_fails_says_so
      plan = Network::Plan.new(profile: 'P', robot: 'r', tasks: [], devices: [], connections: [], order: [])
      error = assert_raises(Syskit::Error) { Render::Svg.write(plan, StringIO.new, dot: 'false') }
      assert_equal "graphviz's dot could not draw the plan (exit status 1)", error.message
      assert_match(/--format dot/, error.hint)
      error = assert_raises(Syskit::Error) { Render::Svg.write(plan, StringIO.new, dot: 'ls') }
      assert_match(/\Agraphviz's dot could not draw the plan \(exit status 2\): ls: /, error.message)
    end

    # A dot killed by a signal (out of memory, a time limit) has no exit
    # status: the message said "exit status )".
    def test_svg_when_dot_is_killed_names_the_signal
      bin = Dir.mktmpdir('syskit-dot')
      (@tmpdirs ||= []) << bin
      File.write(File.join(bin, 'dot'), "#!/bin/sh\nkill -KILL $$\n")
      File.chmod(0o755, File.join(bin, 'dot'))
      path = "#{bin}#{File::PATH_SEPARATOR}#{ENV.fetch('PATH', '')}"
      out, err, status = ENV.stub(:fetch, ->(key, *default) { key == 'PATH' ? path : ENV.to_h.fetch(key, *default) }) do
        run_cli('plan', '--app', EXAMPLE, '--format', 'svg')
      end
      assert_equal [1, ''], [status, out]
      assert_equal "graphviz's dot could not draw the plan (killed by signal SIGKILL)\n  hint: write the graph with " \
                   "--format dot and run dot -Tsvg on it to see what graphviz says\n", err
    end

    def test_svg_without_graphviz_says_what_to_install
      error = assert_raises(Syskit::Error) do
        ENV.stub(:fetch, ->(key, *default) { key == 'PATH' ? '/nonexistent' : ENV.to_h.fetch(key, *default) }) do
          Render::Svg.dot_command
        end
      end
      assert_equal '--format svg needs graphviz, whose dot command is not on PATH', error.message
      assert_match(/install graphviz .* or write the graph with --format dot/, error.hint)
    end

    # Padding comes from a table of widths up to 79; longer names still line up.
    def test_text_aligns_connections_of_any_width
      long = 'x' * 100
      connections = [%w[a out b in], [long, 'out', 'b', 'in']].map do |from, from_port, to, to_port|
        Network::Plan::Connection.new(Network::Plan::Endpoint.new(from, from_port),
                                      Network::Plan::Endpoint.new(to, to_port), '/int', { 'type' => 'data' })
      end
      plan = Network::Plan.new(profile: 'P', robot: 'r', tasks: [], devices: [], connections: connections, order: [])
      lines = Render::Text.render(plan).lines.grep(/ -> /)
      assert_equal ["  a.out#{' ' * 99} -> b.in  /int  data\n", "  #{long}.out -> b.in  /int  data\n"], lines
    end

    def test_dot_escapes_quotes_backslashes_and_line_breaks
      assert_equal '"a\\"b\\\\c\\nd"', Render::Dot.quote("a\"b\\c\nd", +'')
      assert_equal 'a\\{b\\}\\|\\<c\\>\\ d', Render::Dot.record('a{b}|<c> d', +'')
    end

    def test_text_writes_ids_in_hex_and_wraps_long_values
      filters = Array.new(6) { |i| { 'id' => 0x100 + i, 'mask' => 0x7ff, 'name' => "dev#{i}" } }
      task = Network::Plan::Task.with(
        name: 'can0', model: 'hub::Task', deployment: 'can0', devices: [], conf: ['default'], depends_on: [],
        ports: [], operations: [Network::Plan::Operation.new('watch', ['a', 0x10, 0xff], %w[name id mask])],
        properties: [['filters', filters], ['baud', 500_000], ['can_id', 0x181], ['rx_ids', [1, 2]]]
      )
      plan = Network::Plan.new(profile: 'P', robot: 'r', tasks: [task], devices: [], connections: [], order: [])
      text = Render::Text.render(plan)
      assert_includes text, <<-TEXT
    properties  filters: [
                  {"id":0x100,"mask":0x7FF,"name":"dev0"},
                  {"id":0x101,"mask":0x7FF,"name":"dev1"},
      TEXT
      assert_includes text, %(                  {"id":0x105,"mask":0x7FF,"name":"dev5"}\n                ]\n)
      assert_includes text,
                      "                baud: 500000\n                can_id: 0x181\n                rx_ids: [0x1,0x2]\n"
      assert_includes text, "    operations  watch(\"a\", 0x10, 0xFF)\n"
      assert_operator text.lines.map(&:size).max, :<=, 101
    end

    def test_text_lists_tasks_connections_and_order
      text = Render::Text.render(example_plan)
      assert_match(/^Plan of AwesomeRobot::Profiles::Live::Base on robot 'default'$/, text)
      assert_match(/^  can0  canbus::Task  \(deployment can0, conf default\)$/, text)
      assert_match(%r{^  can0\.temperature_sensor +-> temperature_sensor\.can_in +/canbus/Message +buffer 2$}, text)
      assert_match(/^Compositions \(2\)\n  drive  AwesomeRobot::Compositions::Drive  /, text)
      assert_match(/^   2\. configure can0$/, text)
    end
  end
end
