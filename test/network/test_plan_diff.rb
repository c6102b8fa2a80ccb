# frozen_string_literal: true

require 'helper'
require 'syskit/network/plan_diff'
require 'syskit/render/diff_text'

module Syskit
  module Network
    # PlanDiff on plan documents built in memory: what counts as added,
    # removed, changed and moved.
    class TestPlanDiff < Minitest::Test
      def plan(tasks: [], order: [], **lists)
        { 'profile' => 'Bot::Profiles::Base', 'robot' => 'default', 'tasks' => tasks, 'order' => order,
          **lists.transform_keys(&:to_s) }
      end

      def task(name, **values)
        { 'name' => name, 'model' => 'lib::Task', 'deployment' => name, 'conf' => ['default'], 'properties' => {},
          'ports' => [], **values.transform_keys(&:to_s) }
      end

      def port(name, type = '/canbus/Message')
        { 'name' => name, 'direction' => 'output', 'type' => type, 'dynamic' => true }
      end

      def list(diff, name)
        diff.lists.find { |l| l.name == name }
      end

      # [path, old, new] of each change of the first changed entry of +list+.
      def changes(list)
        list.changed.first.changes.map { |c| [c.path, c.old, c.new] }
      end

      def names(entries)
        entries.map { |e| e['name'] }
      end

      def test_identical_plans
        same = plan(tasks: [task('a')], order: [{ 'step' => 'configure', 'task' => 'a' }])
        diff = PlanDiff.new(same, Marshal.load(Marshal.dump(same)))
        assert diff.empty?
        assert(diff.lists.all?(&:empty?))
        assert diff.to_h['identical']
      end

      def test_an_unknown_value_is_no_change
        nan = { 'bias' => Float::NAN, 'gains' => [1.0, Float::NAN] }
        again = { 'bias' => Float::NAN, 'gains' => [1.0, Float::NAN] }
        diff = PlanDiff.new(plan(tasks: [task('a', properties: nan)]), plan(tasks: [task('a', properties: again)]))
        assert diff.empty?
        changed = PlanDiff.new(plan(tasks: [task('a', properties: nan)]),
                               plan(tasks: [task('a', properties: { 'bias' => 1.0, 'gains' => [1.0, 2.0] })]))
        assert_equal [%w[properties bias], %w[properties gains]], changes(list(changed, 'tasks')).map(&:first)
      end

      def test_entries_are_matched_by_key_and_compared_value_by_value
        old = plan(tasks: [task('a', properties: { 'rate' => 1, 'mode' => 'x' }, ports: [port('p'), port('q')]),
                           task('gone')])
        new = plan(tasks: [task('a', properties: { 'rate' => 2, 'mode' => 'x' }, conf: %w[default fast],
                                     ports: [port('q', '/double'), port('r')]),
                           task('new')])
        tasks = list(PlanDiff.new(old, new), 'tasks')
        assert_equal [['new'], ['gone'], ['a']], [names(tasks.added), names(tasks.removed), tasks.changed.map(&:key)]
        assert_equal [[%w[conf], ['default'], %w[default fast]],
                      [%w[properties rate], 1, 2],
                      [%w[ports p], port('p'), nil],
                      [%w[ports q type], '/canbus/Message', '/double'],
                      [%w[ports r], nil, port('r')]], changes(tasks)
      end

      def connection(to, size)
        { 'from' => { 'task' => 'can0', 'port' => to }, 'to' => { 'task' => to, 'port' => 'can_in' },
          'type' => '/canbus/Message', 'policy' => { 'type' => 'buffer', 'size' => size } }
      end

      # A bus with a standard and an extended frame of one number.
      def bus(period)
        { 'name' => 'can0', 'frames' => [{ 'id' => 0x181, 'extended' => false, 'period' => period },
                                         { 'id' => 0x181, 'extended' => true, 'period' => 1 }] }
      end

      def test_connections_by_their_ends_and_frames_by_their_id
        diff = PlanDiff.new(plan(connections: [connection('a', 20), connection('b', 20)], buses: [bus(0.1)]),
                            plan(connections: [connection('a', 40)], buses: [bus(0.2)]))
        connections = list(diff, 'connections')
        assert_equal(['can0.b -> b.can_in'], connections.removed.map { |c| PlanDiff.key('connections', c) })
        assert_equal ['can0.a -> a.can_in', [[%w[policy size], 20, 40]]],
                     [connections.changed.first.key, changes(connections)]
        assert_equal [[%w[frames 181 period], 0.1, 0.2]], changes(list(diff, 'buses'))
      end

      # Where a device is declared moves with every line added above it:
      # that is no change to the robot.
      def test_declarations_moving_in_their_files_are_no_change
        device = ->(line) { { 'name' => 'imu', 'model' => 'IMU', 'declared_at' => "base.rb:#{line}" } }
        assert PlanDiff.new(plan(devices: [device.call(9)]), plan(devices: [device.call(12)])).empty?
      end

      def test_steps_of_the_order_move
        steps = ->(*tasks) { tasks.map { |t| { 'step' => 'start', 'task' => t } } }
        order = list(PlanDiff.new(plan(order: steps.call('a', 'b', 'c', 'd', 'e')),
                                  plan(order: steps.call('a', 'd', 'b', 'c', 'f'))), 'order')
        assert_equal([[{ 'step' => 'start', 'task' => 'd' }, 4, 2]],
                     order.moved.map { |m| [m.key, m.old_position, m.new_position] })
        assert_equal [steps.call('f'), steps.call('e')], [order.added, order.removed]
        swapped = PlanDiff.new(plan(order: steps.call('a', 'b')), plan(order: steps.call('b', 'a')))
        text = Render::DiffText.render(swapped, old_name: 'old.json', new_name: 'new.json')
        assert_equal "Order: 1 moved\n  start b: step 2 -> 1\n", text.split("\n\n").last
      end

      # A list the plan gains (compositions, ...) is compared by the name of
      # its entries, with no change to the diff.
      def test_a_new_list_of_the_plan_is_compared_by_name
        cmp = ->(child) { { 'name' => 'nav', 'model' => 'Nav', 'children' => [{ 'name' => 'pose', 'task' => child }] } }
        diff = PlanDiff.new(plan(compositions: [cmp.call('gps')]), plan(compositions: [cmp.call('imu')]))
        assert_equal [[%w[children pose task], 'gps', 'imu']], changes(list(diff, 'compositions'))
        added = list(PlanDiff.new(plan, plan(compositions: [cmp.call('gps')])), 'compositions').added
        assert_equal ['nav'], names(added)
      end
    end
  end
end
