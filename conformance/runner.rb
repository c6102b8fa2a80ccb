# frozen_string_literal: true

require 'json'
require 'open3'
require 'rbconfig'
require 'tmpdir'

module Syskit
  # Runs Syskit's own model-level test files, read from a checkout of
  # rock-core/tools-syskit, against this gem (their +require
  # "syskit/test/self"+ is lib/syskit/test/self.rb) and counts what passes.
  #
  # Each file runs in a process of its own, from the checkout's root (the
  # files require their fixtures as +./test/fixtures/...+), with a time
  # limit. Nothing of the checkout is copied into the project.
  class Conformance
    # The in-scope files: the model-level ones (SPEC section 14).
    PATTERNS = %w[
      test/models/test_*.rb test/robot/test_*.rb test/queries/test_*.rb
      test/actions/test_profile.rb test/test/test_profile_assertions.rb
      test/test/test_network_manipulation.rb test/test/test_stub_network.rb
    ].freeze
    TOP_LEVEL = %w[
      bound_data_service component composition connection_graph connection_graphs data_flow data_service
      dependency_injection dependency_injection_context exceptions instance_requirements instance_selection
      orogen_namespace placeholder port properties task_context
    ].map { |name| "test/test_#{name}.rb" }.freeze
    # Files the project's case list (shared/conformance) counts too: the
    # network generation tests, none of whose cases is model-level.
    NETWORK_GENERATION = 'test/network_generation/test_*.rb'

    TIMEOUT = 300
    LIB = File.expand_path('../lib', __dir__)

    # One file's counts.
    FileResult = Struct.new(:file, :results, :load_error, :seconds, keyword_init: true) do
      def count(outcome)
        results.count { |r| r['result'] == outcome }
      end

      def runtime_skips
        results.count { |r| r['result'] == 'skip' && r['message'].include?('runtime') }
      end

      def other_skips
        count('skip') - runtime_skips
      end
    end

    attr_reader :source, :cases

    # +source+: the tools-syskit checkout; +cases+: the project's case list
    # (a TSV of file, line, class A/B/C, ..., minitest class, method), when
    # there is one, to count model-level (A) cases.
    def initialize(source, cases: nil, jobs: 2)
      @source = File.expand_path(source)
      @cases = cases && File.file?(cases) ? Conformance.read_cases(cases) : nil
      @jobs = jobs
    end

    def self.read_cases(path)
      File.readlines(path, chomp: true).reject { |l| l.start_with?('#') || l.strip.empty? }.to_h do |line|
        fields = line.split("\t")
        [[fields[5], fields[6]], fields[2]]
      end
    end

    def files
      found = (PATTERNS + TOP_LEVEL + [NETWORK_GENERATION]).flat_map do |pattern|
        Dir.glob(pattern, base: source).sort
      end
      found.uniq
    end

    # Runs every file (+only+: those whose path contains it) and returns
    # their FileResults.
    def run(only: nil)
      queue = Queue.new
      files.select { |f| only.nil? || f.include?(only) }.each { |f| queue << f }
      queue.close
      results = []
      lock = Mutex.new
      Array.new(@jobs) do
        Thread.new do
          while (file = queue.pop)
            result = run_file(file)
            lock.synchronize { results << result }
          end
        end
      end.each(&:join)
      results.sort_by(&:file)
    end

    def run_file(file)
      Dir.mktmpdir('syskit-conformance') do |dir|
        report = File.join(dir, 'report.jsonl')
        env = { 'SYSKIT_CONFORMANCE_REPORT' => report }
        started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        out, status = Open3.capture2e(env, 'timeout', TIMEOUT.to_s, RbConfig.ruby, '-I', LIB, file,
                                      chdir: source)
        seconds = Process.clock_gettime(Process::CLOCK_MONOTONIC) - started
        results = File.file?(report) ? File.readlines(report).map { |l| JSON.parse(l) } : []
        load_error = load_error_of(out, status) if results.empty?
        FileResult.new(file: file, results: results, load_error: load_error, seconds: seconds)
      end
    end

    def load_error_of(output, status)
      return "timed out after #{TIMEOUT} s" if status.exitstatus == 124

      line = output.lines.find { |l| l =~ /Error|error/ } || output.lines.last
      line.to_s.strip[0, 300]
    end

    # The model-level (A) cases' counts: pass, fail, error, skip, not run.
    def model_level_counts(results)
      return nil unless cases

      outcomes = results.flat_map(&:results).to_h { |r| [[r['class'], r['name']], r['result']] }
      counts = Hash.new(0)
      cases.each do |key, klass|
        next unless klass == 'A'

        counts[outcomes.fetch(key, 'not run')] += 1
      end
      counts
    end
  end
end
