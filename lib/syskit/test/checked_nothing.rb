# frozen_string_literal: true

module Syskit
  module Test
    # A minitest reporter that lists, after the run, the tests that passed
    # without a single assertion: a test whose checks never ran (an empty
    # +it+, a loop over an empty list, a +flunk ... if+ whose condition is
    # never true) passes whatever the robot. They do not fail the run (as
    # in Syskit, whose tests a bundle may run unchanged), but each is named
    # at its file:line with how to fix it.
    class CheckedNothing < Minitest::AbstractReporter
      def initialize(io)
        super()
        @io = io
        @tests = []
      end

      def record(result)
        @tests << result if result.passed? && !result.skipped? && result.assertions.zero?
      end

      def report
        return if @tests.empty?

        @io.puts "\n#{@tests.size} test(s) passed without checking anything (no assertion ran):"
        @tests.sort_by(&:source_location).each do |result|
          path, line = result.source_location
          @io.puts "#{Location.new(path, line).to_s(Dir.pwd)}: #{result.klass}##{result.name}"
        end
        @io.puts '  hint: assert what the test expects (assert_equal, assert_raises, is_configurable...), ' \
                 'or remove the test'
      end
    end
  end
end

# minitest's plugin interface: Minitest.run calls plugin_NAME_init for each
# name in Minitest.extensions.
Minitest.define_singleton_method(:plugin_syskit_checked_nothing_init) do |options|
  reporter << Syskit::Test::CheckedNothing.new(options[:io])
end
Minitest.extensions << 'syskit_checked_nothing' unless Minitest.extensions.include?('syskit_checked_nothing')
