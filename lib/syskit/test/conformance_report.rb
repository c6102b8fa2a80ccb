# frozen_string_literal: true

require 'json'

module Syskit
  module Test
    # With SYSKIT_CONFORMANCE_REPORT=FILE, each test run through
    # syskit/test/self appends one JSON line to FILE: its class, name,
    # result (pass, fail, error, skip) and message. `rake conformance`
    # reads these to count Syskit's own test cases.
    module ConformanceReport
      def self.path
        ENV.fetch('SYSKIT_CONFORMANCE_REPORT', nil)
      end

      def self.record(result)
        line = { class: result.klass, name: result.name, result: outcome(result),
                 message: result.failure&.message.to_s[0, 2000] }
        File.open(path, 'a') { |io| io.puts(JSON.generate(line)) }
      end

      def self.outcome(result)
        if result.skipped? then 'skip'
        elsif result.passed? then 'pass'
        elsif result.error? then 'error'
        else
          'fail'
        end
      end

      def run
        result = super
        ConformanceReport.record(result) if ConformanceReport.path
        result
      end
    end
  end
end

Minitest::Test.prepend(Syskit::Test::ConformanceReport)
