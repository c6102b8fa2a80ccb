# frozen_string_literal: true

require 'helper'
require 'psych'

module Syskit
  # The corpus of broken apps, test/fixtures/broken/<case>/: each is a small
  # app with one defect and an expected.yml saying what a user must see:
  #
  #   command: check                   # or plan, gen (default: check)
  #   args: [Base, gsp_dev]            # optional, after the command
  #   location: models/profiles/base.rb:8   # the line where the user must act
  #                                         # (a path alone for a directory: models)
  #   message: needs a name|as:        # a regexp the first line's message matches
  #
  # For every case, `syskit <command> --app <case>` must exit with status 1
  # and print, first (stdout for check, stderr for plan), the line
  # "<location>: <message>" followed by "  hint: ...", with no backtrace
  # (unless --trace), no internal error, and without touching the app's files.
  #
  # `ruby -Ilib -Itest test/test_broken_corpus.rb` ends with a table of the
  # failing cases: what was expected and what was printed.
  class TestBrokenCorpus < Minitest::Test
    extend SelfTest::Long

    CORPUS = File.expand_path('fixtures/broken', __dir__)
    BACKTRACE = /\.rb:\d+:in `/
    HINT = /\A  hint: \S/

    # One case of the corpus.
    Case = Struct.new(:name, :dir, :description, :command, :args, :location, :message, keyword_init: true) do
      def self.load(dir)
        expected = Psych.safe_load(File.read(File.join(dir, 'expected.yml')))
        new(name: File.basename(dir), dir: dir, description: expected['description'],
            command: expected.fetch('command', 'check'), args: Array(expected['args']).map(&:to_s),
            location: expected.fetch('location'), message: Regexp.new(expected.fetch('message')))
      end

      def command_line(*extra)
        ['syskit', command, *args, '--app', File.join('test/fixtures/broken', name), *extra].join(' ')
      end

      def expected_line
        "#{location}: /#{message.source}/"
      end

      # The stream the first line is read from: check reports on stdout,
      # the other commands print errors on stderr.
      def stream
        command == 'check' ? :stdout : :stderr
      end
    end

    # What one run printed, and how it measures up against the case.
    class Outcome
      attr_reader :kase, :out, :err, :status, :problems

      def initialize(kase, out, err, status, changed_files)
        @kase = kase
        @out = out
        @err = err
        @status = status
        @problems = []
        measure(changed_files)
      end

      def primary
        kase.stream == :stderr ? err : out
      end

      def secondary
        kase.stream == :stderr ? out : err
      end

      # The lines the user reads first: the expected stream's, or the other
      # one's when it printed nothing.
      def lines
        text = primary.strip.empty? ? secondary : primary
        text.lines.map(&:chomp).drop_while { |l| l.strip.empty? }
      end

      def first_line
        lines.first.to_s
      end

      def failed?
        problems.any?
      end

      def report
        printed = lines.first(2).map { |l| "            #{l}" }.join("\n").sub(/\A\s+/, '')
        <<~TEXT
          [#{kase.name}] #{kase.description}
            run:      #{kase.command_line}
            expected: #{kase.expected_line}
                        hint: ...
            printed:  #{printed.empty? ? '(nothing)' : printed}
            problems: #{problems.map { |kind, text| "#{kind}: #{text}" }.join("\n                      ")}
          #{full_output}
        TEXT
      end

      private

      def measure(changed_files)
        check_status
        check_first_line
        check_hint
        problem(:internal_error, 'the CLI reports an internal error') if (out + err).include?('internal error')
        problem(:backtrace, 'a backtrace is shown without --trace') if (out + err).match?(BACKTRACE)
        problem(:files_changed, changed_files.join(', ')) unless changed_files.empty?
      end

      def check_status
        problem(:exit_status, "exit status #{status.inspect}, expected 1") unless status == 1
      end

      def check_first_line
        first = first_line
        if first.empty?
          problem(:nothing_printed, "nothing on #{kase.stream}")
        elsif !first.start_with?("#{kase.location}: ")
          where = first[/\A(\S+?:\d+): /, 1]
          problem(:location, "#{where ? "at #{where}" : 'no file:line at the start'}, expected #{kase.location}")
        end
        message = first.sub(/\A\S+?:\d+: /, '')
        problem(:message, "does not match /#{kase.message.source}/") unless message.match?(kase.message)
        return unless primary.strip.empty? && !first.empty?

        problem(:stream, "printed on the wrong stream (expected #{kase.stream})")
      end

      def check_hint
        problem(:hint, 'the first line is not followed by a "  hint: ..." line') unless lines[1].to_s.match?(HINT)
      end

      def problem(kind, text)
        @problems << [kind, text]
      end

      def full_output
        text = +''
        text << "  stdout:\n#{indent(out)}\n" unless out.strip.empty?
        text << "  stderr:\n#{indent(err)}\n" unless err.strip.empty?
        text
      end

      def indent(text)
        text.lines.first(12).map { |l| "    | #{l.chomp}" }.join("\n")
      end
    end

    FAILED = [] # rubocop:disable Style/MutableConstant -- filled while the tests run, for the final table

    def self.case_dirs
      Dir[File.join(CORPUS, '*', 'expected.yml')].map { |p| File.dirname(p) }.sort
    end

    case_dirs.each do |dir|
      kase = Case.load(dir)
      define_method("test_#{kase.name}") do
        outcome = run_case(kase)
        FAILED << outcome if outcome.failed?
        assert_empty outcome.problems, -> { outcome.report }
      end
    end

    def test_the_corpus_covers_enough_cases
      assert_operator self.class.case_dirs.size, :>=, 45
    end

    def test_every_case_has_a_valid_expectation
      self.class.case_dirs.each do |dir|
        kase = Case.load(dir)
        assert_includes %w[check plan gen], kase.command, kase.name
        assert_match(/\A\S+?(:\d+)?\z/, kase.location, kase.name)
        path = File.join(dir, kase.location.sub(/:\d+\z/, ''))
        # A located case names a file, or what only looks like one (a
        # directory named x.rb, a dangling symlink).
        exists = File.exist?(path) || File.symlink?(path)
        assert exists, "#{kase.name}: #{kase.location} does not exist"
      end
    end

    # With --trace, the user asked for the backtrace: it must be there.
    def test_plan_with_trace_shows_the_backtrace
      kase = Case.load(File.join(CORPUS, 'configure_raises_plan'))
      out, err, status = run_cli(kase.command, '--app', kase.dir, '--trace')
      assert_equal 1, status
      assert_match BACKTRACE, err, "no backtrace with --trace:\n#{out}#{err}"
    end

    def test_plan_with_trace_of_a_declaration_error_shows_the_backtrace
      kase = Case.load(File.join(CORPUS, 'two_drivers_without_using_plan'))
      out, err, status = run_cli(kase.command, '--app', kase.dir, '--trace')
      assert_equal 1, status
      assert_match BACKTRACE, err, "no backtrace with --trace:\n#{out}#{err}"
    end

    def test_check_with_trace_shows_the_backtrace
      kase = Case.load(File.join(CORPUS, 'configure_raises'))
      out, err, status = run_cli(kase.command, '--app', kase.dir, '--trace')
      assert_equal 1, status
      assert_match BACKTRACE, out + err, "no backtrace with --trace:\n#{out}#{err}"
    end

    private

    def run_case(kase)
      before = snapshot(kase.dir)
      begin
        out, err, status = run_cli(kase.command, *kase.args, '--app', kase.dir)
      rescue StandardError, ScriptError => e
        out = ''
        err = "internal error (escaped the CLI): #{e.class}: #{e.message}\n"
        status = nil
      end
      Outcome.new(kase, out, err, status, changed_files(before, snapshot(kase.dir)))
    end

    # Every entry of +dir+ with its content (files) and modification time.
    def snapshot(dir)
      Dir.glob('**/*', File::FNM_DOTMATCH, base: dir).reject { |p| File.basename(p) == '.' }.sort.to_h do |path|
        full = File.join(dir, path)
        [path, [File.file?(full) ? File.binread(full) : File.ftype(full), File.lstat(full).mtime]]
      end
    end

    def changed_files(before, after)
      (before.keys | after.keys).reject { |path| before[path] == after[path] }.map do |path|
        state = if !before.key?(path) then 'created'
                elsif !after.key?(path) then 'deleted'
                else 'modified'
                end
        "#{path} (#{state})"
      end
    end
  end

  if File.expand_path($PROGRAM_NAME) == File.expand_path(__FILE__)
    Minitest.after_run do
      failed = TestBrokenCorpus::FAILED.sort_by { |o| o.kase.name }
      total = TestBrokenCorpus.case_dirs.size
      puts "\n#{'=' * 78}\nBroken corpus: #{failed.size} of #{total} cases fail\n#{'=' * 78}"
      severity = %i[internal_error backtrace exit_status nothing_printed location message hint stream files_changed]
      failed.group_by { |o| o.problems.map(&:first).min_by { |k| severity.index(k) || severity.size } }
            .sort_by { |kind, _| severity.index(kind) || severity.size }.each do |kind, outcomes|
        puts "\n## #{kind} (#{outcomes.size})"
        outcomes.each do |o|
          puts "- #{o.kase.name}  [#{o.problems.map(&:first).uniq.join(', ')}]"
          puts "    expected: #{o.kase.expected_line}"
          puts "    printed:  #{o.first_line.empty? ? '(nothing)' : o.first_line}"
          puts "              #{o.lines[1]}" if o.lines[1]
        end
      end
    end
  end
end
