# frozen_string_literal: true

require 'helper'

module Syskit
  module Network
    # Merge's index of the tasks a merge group keeps: it must find the task
    # that comparing the inputs of every kept task, in order, finds.
    class TestKeptTasks < Minitest::Test
      PORTS = %w[a b c].freeze

      # Inputs on some of the ports, each fed by one or two of a few sources.
      def random_inputs(random)
        PORTS.select { random.rand(2).zero? }.to_h do |port|
          [port, Array.new(random.rand(1..2)) { [random.rand(3), 'out'] }.sort]
        end
      end

      def agree?(mine, theirs)
        (mine.keys & theirs.keys).all? { |port| mine[port] == theirs[port] }
      end

      def test_finds_the_first_kept_task_whose_inputs_agree
        random = Random.new(28)
        20.times do
          kept = Merge::KeptTasks.new
          reference = []
          merged = 0
          60.times do |task|
            inputs = random_inputs(random)
            expected = reference.find { |_, other| agree?(other, inputs) }&.first
            found = kept.first_agreeing(inputs)
            expected.nil? ? assert_nil(found) : assert_equal(expected, found, "inputs #{inputs} among #{reference}")
            next merged += 1 if found

            kept.add(task, inputs)
            reference << [task, inputs]
          end
          assert_equal reference.size, kept.size
          assert_operator merged, :positive?
        end
      end

      def test_tasks_fed_alike_merge_and_others_stay
        kept = Merge::KeptTasks.new
        kept.add(:first, { 'in' => [[1, 'out']] })
        kept.add(:second, { 'in' => [[2, 'out']] })
        assert_equal :second, kept.first_agreeing({ 'in' => [[2, 'out']] })
        assert_nil kept.first_agreeing({ 'in' => [[3, 'out']] })
        assert_equal :first, kept.first_agreeing({}), 'a task with no input agrees with any'
        assert_equal :first, kept.first_agreeing({ 'other' => [[3, 'out']] })
      end
    end
  end
end
