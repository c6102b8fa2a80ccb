# frozen_string_literal: true

require 'helper'
require 'timeout'

module Syskit
  # Random mutations of working apps (a profile, an .orogen spec, a YAML
  # configuration file, an extension file, a robot configuration,
  # config/syskit.yml): whatever
  # the mutation, `syskit check` must either succeed or report Syskit errors
  # that each start with the user's file:line, never an internal error, a
  # backtrace, or a hang.
  #
  # Bounded and deterministic: a fixed seed, at most ITERATIONS runs and
  # BUDGET seconds of CPU (so that a loaded machine runs as many). Each
  # iteration has its own random generator, so one can be replayed alone:
  #
  #   SYSKIT_FUZZ_SEED=1 SYSKIT_FUZZ_ONLY=123 ruby -Ilib -Itest test/test_fuzz.rb
  #
  # The suite runs the seed's first 300 mutations (about 5 s of CPU); a
  # longer campaign, or another seed, finds more:
  #
  #   SYSKIT_FUZZ_ITERATIONS=5000 SYSKIT_FUZZ_SECONDS=300 SYSKIT_FUZZ_SEED=7 \
  #     ruby -Ilib -Itest test/test_fuzz.rb
  #
  # In the suite, the iterations run in a process of their own, beside the
  # tests that load apps in the suite's process (see
  # SelfTest::SuiteRunner); that process runs this file with
  # SYSKIT_FUZZ_IN_PROCESS set.
  class TestFuzz < Minitest::Test
    parallelize_me! unless ENV['SYSKIT_FUZZ_IN_PROCESS']
    extend SelfTest::Long

    SEED = Integer(ENV.fetch('SYSKIT_FUZZ_SEED', '20_250_601').delete('_'))
    ITERATIONS = Integer(ENV.fetch('SYSKIT_FUZZ_ITERATIONS', '300'))
    BUDGET = Float(ENV.fetch('SYSKIT_FUZZ_SECONDS', '12'))
    ONLY = ENV['SYSKIT_FUZZ_ONLY']&.then { |i| Integer(i) }
    RUN_TIMEOUT = 5
    BACKTRACE = /\.rb:\d+:in `/
    LOCATED = /\A(?<path>\S+?):(?<line>\d+): \S/
    GEM_LIB = File.join(SelfTest::GEM_ROOT, 'lib', '')

    # Raised by Timeout in a run that takes too long. Not a StandardError,
    # so that the CLI's own rescue clauses cannot swallow it.
    class Hang < Exception; end # rubocop:disable Lint/InheritException

    # The working apps and the files mutated in each, with their weight.
    # Configuration files, a second robot configuration and a fuller
    # config/syskit.yml are added to the seed apps so there is YAML and
    # robot configuration to mutate.
    SYSKIT_YML = "# the app's name and the acronyms its names keep\nname: MyApp\nacronyms: [CAN, GPS, IMU]\n"
    BASES = {
      'can_bus' => {
        extra: { 'config/orogen/canbus::Task.yml' => <<~YAML, 'config/syskit.yml' => SYSKIT_YML },
          --- name:default
          device: can0
          checkBusOkInterval: 100
          --- name:slow
          statsInterval: 5000
        YAML
        targets: {
          'models/profiles/base.rb' => 3, 'models/orogen/can_temperature_sensor.orogen' => 3,
          'config/orogen/canbus::Task.yml' => 3, 'models/orogen/can_temperature_sensor.rb' => 1,
          'config/robots/default.rb' => 2, 'config/syskit.yml' => 2
        }
      },
      'demux' => {
        extra: { 'config/orogen/canbus::Task.yml' => <<~YAML, 'config/syskit.yml' => SYSKIT_YML },
          --- name:default
          devices:
            - name: temperature_sensor
              id: 4660
              mask: 65535
        YAML
        targets: {
          'models/profiles/base.rb' => 3, 'models/orogen/canbus.orogen' => 3,
          'config/orogen/canbus::Task.yml' => 3, 'models/orogen/canbus.rb' => 2,
          'models/typekits/my_bus.rb' => 1, 'config/robots/default.rb' => 2, 'config/syskit.yml' => 2
        }
      },
      'cameras' => {
        extra: { 'config/robots/sim.rb' => <<~RUBY, 'config/syskit.yml' => SYSKIT_YML },
          # the cameras of the simulator, one deployment for both
          Syskit.conf.use_deployment OroGen.camera_gige.Task => 'forward_camera'
          Syskit.conf.use_deployment OroGen.camera_gige.Task => 'aft_camera'
        RUBY
        targets: {
          'models/profiles/base.rb' => 3, 'models/orogen/camera_gige.orogen' => 3,
          'config/orogen/camera_gige::Task.yml' => 3, 'config/robots/default.rb' => 2,
          'config/robots/sim.rb' => 2, 'config/syskit.yml' => 2
        }
      }
    }.freeze

    TOKENS = [
      'nil', 'end', ')', '(', ':', ',', 'do', '0', '-1', '42', '3.5', '0x1fffffff', '0x20000000',
      '99999999999999999999', 'foo_bar', 'Unknown', 'Devices::Nope', ':sym', "'str'", '""', '[]', '{}', '|',
      '.', '::', '=>', '?', '!', '@x', 'true', 'false', 'self', 'super', 'yield', '*', '&', '%', '~', '#',
      '---', '--- name:default', '- ', '&a', '*a', '!ruby/object:Object', '!!binary', 'name:x', "\t", '"',
      "'", '/', '/^w/', 'as:', "as: 'x'", 'using:', 'OroGen', 'OroGen.nope', 'Types', '.can_id(1, 2)',
      '.with_conf', "'default'", 'device', 'through', 'com_bus', 'task_context', 'property', 'input_port',
      'output_port', 'dynamic_output_port', 'provides', 'driver_for', '/canbus/Message', '/nope/Type', '[1, 2]',
      '{ a: 1 }', 'key: value', 'properties', 'each_declared_attached_device', 'robot',
      # configuration files and syskit.yml: values a plan cannot hold, odd YAML
      '.nan', '.inf', '-.inf', '1e400', '!!binary /w==', '!!float', '~', 'name:', 'acronyms:', '[CAN, ]',
      'name: 9lives', 'name: My::App', '? [a]', '<<: *a', '|', '>-', '"\\xff"', '0o777', '2025-06-01',
      # robot configurations
      'Syskit.conf', '.use_deployment', "use_deployment 'nope'", "OroGen.camera_gige.Task => 'x'",
      "=> 'temperature_sensor'", 'Robot.requires', 'Syskit.conf.use_deployment nil'
    ].freeze

    MUTATIONS = %i[delete_line duplicate_line swap_lines flip_char truncate insert_token insert_line
                   replace_word].freeze

    # Applies random mutations to a text, remembering what it did.
    class Mutator
      attr_reader :log

      def initialize(random)
        @random = random
        @log = []
      end

      def mutate(text, count)
        count.times { text = send(MUTATIONS[@random.rand(MUTATIONS.size)], text) }
        text
      end

      private

      def line_index(lines)
        @random.rand([lines.size, 1].max)
      end

      def delete_line(text)
        lines = text.lines
        i = line_index(lines)
        @log << "delete line #{i + 1}: #{lines[i].inspect}"
        lines.delete_at(i)
        lines.join
      end

      def duplicate_line(text)
        lines = text.lines
        i = line_index(lines)
        @log << "duplicate line #{i + 1}: #{lines[i].inspect}"
        lines.insert(i, lines[i].to_s)
        lines.join
      end

      def swap_lines(text)
        lines = text.lines
        i = line_index(lines)
        j = line_index(lines)
        @log << "swap lines #{i + 1} and #{j + 1}"
        lines[i], lines[j] = lines[j], lines[i]
        lines.join
      end

      def flip_char(text)
        return text if text.empty?

        i = @random.rand(text.size)
        char = (32..126).to_a.sample(random: @random).chr
        @log << "replace #{text[i].inspect} at offset #{i} with #{char.inspect}"
        text[0...i] + char + text[(i + 1)..]
      end

      def truncate(text)
        i = @random.rand(text.size + 1)
        @log << "truncate at offset #{i}"
        text[0...i]
      end

      def insert_token(text)
        i = @random.rand(text.size + 1)
        token = TOKENS.sample(random: @random)
        @log << "insert #{token.inspect} at offset #{i}"
        "#{text[0...i]} #{token} #{text[i..]}"
      end

      def insert_line(text)
        lines = text.lines
        i = @random.rand(lines.size + 1)
        token = TOKENS.sample(random: @random)
        @log << "insert line #{i + 1}: #{token.inspect}"
        lines.insert(i, "#{token}\n")
        lines.join
      end

      def replace_word(text)
        words = text.to_enum(:scan, /\w+/).map { Regexp.last_match }
        return insert_token(text) if words.empty?

        word = words.sample(random: @random)
        token = TOKENS.sample(random: @random)
        @log << "replace #{word[0].inspect} at offset #{word.begin(0)} with #{token.inspect}"
        text[0...word.begin(0)] + token + text[word.end(0)..]
      end
    end

    # One iteration: which app, which file, what was done, what was printed.
    Run = Struct.new(:iteration, :base, :target, :mutations, :content, :out, :err, :status, :problems,
                     keyword_init: true) do
      def report
        <<~TEXT
          --- iteration #{iteration} (SYSKIT_FUZZ_SEED=#{SEED} SYSKIT_FUZZ_ONLY=#{iteration}): #{base}, #{target}
          problems: #{problems.join('; ')}
          mutations: #{mutations.join('; ')}
          exit status: #{status.inspect}
          output:
          #{(out + err).lines.first(8).map { |l| "  | #{l}" }.join.chomp}
          mutated #{target}:
          #{content.lines.each_with_index.map { |l, i| format('  %<n>3d| %<line>s', n: i + 1, line: l) }.join.chomp}
        TEXT
      end
    end

    def setup
      super
      @work = Dir.mktmpdir('syskit-fuzz')
      @templates = BASES.to_h do |name, base|
        files = read_tree(fixture('seed', name)).reject { |path, _| path.start_with?('test/') }
        [name, files.merge(base[:extra])]
      end
    end

    def teardown
      FileUtils.rm_rf(@work)
      super
    end

    def test_mutated_apps_fail_with_located_errors_only
      return in_a_process_of_its_own unless ENV['SYSKIT_FUZZ_IN_PROCESS'] || ONLY

      check_the_bases_work
      started = now
      runs = []
      iterations = ONLY ? [ONLY] : (0...ITERATIONS)
      iterations.each do |iteration|
        break if now - started > BUDGET

        runs << run_iteration(iteration)
      end
      failed = runs.select { |r| r.problems.any? }
      print_summary(runs, failed, now - started)
      assert_operator runs.size, :>=, [50, iterations.size].min, 'too few iterations ran within the time budget'
      assert failed.empty?, failure_report(failed)
    end

    private

    # Runs this test in a Ruby process of its own, and gives its summary and
    # failures.
    def in_a_process_of_its_own
      out, err, status = Open3.capture3(SelfTest.child_env.merge('SYSKIT_FUZZ_IN_PROCESS' => '1'), RbConfig.ruby,
                                        '-Ilib', '-Itest', __FILE__, '-n', "/#{name}/",
                                        chdir: SelfTest::GEM_ROOT, unsetenv_others: true)
      assert status.success?, "the fuzz process failed:\n#{out}#{err}"
      summary = out[/^fuzz: .*$/]
      assert summary, "the fuzz process ran no iteration:\n#{out}#{err}"
      # On the terminal's stdout: this thread runs beside tests that take
      # $stdout over to read what the CLI prints.
      STDOUT.puts "\n#{summary}" # rubocop:disable Style/GlobalStdStream
    end

    def print_summary(runs, failed, elapsed)
      puts format("\nfuzz: %<n>d iterations (seed %<seed>d) in %<t>.1fs of CPU, %<ok>d accepted, " \
                  '%<err>d located errors, %<bad>d failures',
                  n: runs.size, seed: SEED, t: elapsed, ok: runs.count { |r| r.status&.zero? },
                  err: runs.count { |r| r.status == 1 && r.problems.empty? }, bad: failed.size)
    end

    # The CPU time of this process: the budget holds as many iterations
    # whatever else the machine runs.
    def now
      Process.clock_gettime(Process::CLOCK_PROCESS_CPUTIME_ID)
    end

    def read_tree(dir)
      Dir.glob('**/*', base: dir).select { |p| File.file?(File.join(dir, p)) }.sort.to_h do |path|
        [path, File.read(File.join(dir, path))]
      end
    end

    # The unmutated apps must pass, or every mutation would look like a find.
    def check_the_bases_work
      @templates.each do |name, files|
        dir = write_files(File.join(@work, "base-#{name}"), files)
        out, err, status = run_cli('check', '--app', dir)
        assert_equal 0, status, "the #{name} base app does not pass syskit check:\n#{out}#{err}"
      end
    end

    def run_iteration(iteration)
      random = Random.new((SEED * 1_000_003) + iteration)
      base = BASES.keys[iteration % BASES.size]
      target = pick_target(BASES[base][:targets], random)
      mutator = Mutator.new(random)
      files = @templates[base].dup
      files[target] = mutator.mutate(files.fetch(target), 1 + random.rand(3))
      dir = write_files(File.join(@work, "run-#{iteration}", 'my_app'), files)
      out, err, status, problems = check(dir)
      FileUtils.rm_rf(File.dirname(dir))
      Run.new(iteration: iteration, base: base, target: target, mutations: mutator.log, content: files[target],
              out: out, err: err, status: status, problems: problems)
    end

    def pick_target(targets, random)
      weighted = targets.flat_map { |path, weight| [path] * weight }
      weighted[random.rand(weighted.size)]
    end

    def write_files(dir, files)
      files.each do |path, content|
        full = File.join(dir, path)
        FileUtils.mkdir_p(File.dirname(full))
        File.write(full, content)
      end
      dir
    end

    # Runs syskit check on +dir+; returns its output and what is wrong with it.
    def check(dir)
      result =
        begin
          out, err, status = Timeout.timeout(RUN_TIMEOUT, Hang) { run_cli('check', '--app', dir) }
          [out, err, status, judge(out, err, status)]
        rescue Hang
          ['', '', nil, ["hang: no answer within #{RUN_TIMEOUT}s"]]
        rescue StandardError, ScriptError => e
          ['', "#{e.class}: #{e.message}", nil, ["escaped the CLI: #{e.class}: #{e.message.lines.first&.chomp}"]]
        end
      if Syskit.app
        Syskit.app.unload
        result[3] += ['the app was left loaded']
      end
      result
    end

    def judge(out, err, status)
      # What a mutation puts in a message may not be text (a !!binary key).
      text = (out + err).scrub
      problems = []
      problems << text[/internal error: .*/] if text.include?('internal error')
      problems << 'backtrace without --trace' if text.match?(BACKTRACE)
      problems << "exit status #{status.inspect}" unless [0, 1].include?(status)
      return problems unless status == 1

      errors = error_lines(text)
      problems << 'exit status 1 but no error printed' if errors.empty?
      errors.each { |line| problems.concat(line_problems(line)) }
      problems.uniq
    end

    # An error line must start with a line of the user's files.
    def line_problems(line)
      m = line.match(LOCATED)
      return [unlocated(line)] unless m

      problems = []
      problems << "line 0: #{line}" if m[:line].to_i.zero?
      problems << "located in syskit's own code: #{line}" if File.expand_path(m[:path], '/').start_with?(GEM_LIB)
      problems
    end

    # The lines of the output that state problems: not hints, not the
    # summary line of syskit check.
    def error_lines(text)
      text.lines.map(&:chomp).reject do |line|
        line.strip.empty? || line.start_with?('  ') || line.match?(/\A\S+: \d+ error\(s\), \d+ warning\(s\)\z/)
      end
    end

    def unlocated(line)
      "no file:line: #{line[0, 200]}"
    end

    def failure_report(failed)
      return '' if failed.empty?

      # One report per kind of problem (the first words of its first problem).
      kinds = failed.group_by { |r| r.problems.first.sub(/(: |\s*\().*/m, '') }
      summary = failed.map { |r| "  #{r.iteration}: #{r.problems.first[0, 160]}" }.first(40).join("\n")
      details = failed.uniq { |r| r.problems.first[0, 60] }.first(15).map(&:report).join("\n")
      "#{failed.size} mutated apps broke the error reporting (#{kinds.keys.join(', ')}):\n" \
        "#{summary}\n\nFirst of each kind:\n#{details}"
    end
  end
end
