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

    def test_json_has_the_keys_of_the_spec
      doc = JSON.parse(Render::JSON.render(example_plan))
      assert_equal %w[profile robot tasks devices connections order buses], doc.keys
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

    def test_dot_is_accepted_by_graphviz
      dot = Render::Dot.render(example_plan)
      assert_match(/\Adigraph "AwesomeRobot::Profiles::Live::Base" \{/, dot)
      assert_match(/"can0" -> "temperature_sensor" \[label="temperature_sensor -> can_in\\nbuffer 2"\];/, dot)
      skip 'graphviz (dot) is not installed' unless system('command -v dot >/dev/null 2>&1')

      svg, err, status = Open3.capture3('dot', '-Tsvg', stdin_data: dot)
      assert status.success?, err
      assert_match(/<svg/, svg)
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
    end

    def test_text_lists_tasks_connections_and_order
      text = Render::Text.render(example_plan)
      assert_match(/^Plan of AwesomeRobot::Profiles::Live::Base on robot 'default'$/, text)
      assert_match(/^  can0  canbus::Task  \(deployment can0, conf default\)$/, text)
      assert_match(%r{^  can0\.temperature_sensor +-> temperature_sensor\.can_in +/canbus/Message  buffer 2$}, text)
      assert_match(/^   2\. configure can0$/, text)
    end
  end
end
