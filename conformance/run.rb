# frozen_string_literal: true

# rake conformance SYSKIT_SOURCE=DIR [ONLY=test/models] [CASES=FILE] [OUT=FILE]
#
# Runs Syskit's own model-level test files from a checkout of
# rock-core/tools-syskit against this gem, and prints per file what passed,
# failed, errored and skipped (runtime skips apart), then the totals.
# OUT=FILE writes every case's outcome as JSON lines too.
require_relative 'runner'

source = ENV.fetch('SYSKIT_SOURCE', nil)
if source.nil? || source.empty?
  puts 'rake conformance: skipped, no checkout of rock-core/tools-syskit given ' \
       '(SYSKIT_SOURCE=DIR; fetch one with git clone)'
  exit 0
end
unless File.directory?(File.join(source, 'test', 'models'))
  abort "rake conformance: #{source} is not a checkout of rock-core/tools-syskit (no test/models/ in it)"
end

default_cases = File.expand_path('../../shared/conformance/syskit_model_cases.tsv', __dir__)
cases = ENV.fetch('CASES', default_cases)
warn "no case list at #{cases}: the model-level totals are left out (pass CASES=FILE)" unless File.file?(cases)
conformance = Syskit::Conformance.new(source, cases: cases)
results = conformance.run(only: ENV.fetch('ONLY', nil))

format_row = '%-52<file>s %5<pass>s %5<fail>s %5<error>s %8<runtime>s %5<skip>s  %<note>s'
puts format(format_row, file: 'file', pass: 'pass', fail: 'fail', error: 'error', runtime: 'runtime',
                        skip: 'skip', note: '')
totals = { pass: 0, fail: 0, error: 0, runtime: 0, skip: 0 }
results.each do |r|
  row = { pass: r.count('pass'), fail: r.count('fail'), error: r.count('error'), runtime: r.runtime_skips,
          skip: r.other_skips }
  row.each { |k, v| totals[k] += v }
  note = r.load_error ? "does not load: #{r.load_error}" : format('%.1f s', r.seconds)
  puts format(format_row, file: r.file, **row, note: note)
end
puts format(format_row, file: "total (#{results.size} files, #{results.count(&:load_error)} not loading)",
                        **totals, note: '')

if (counts = conformance.model_level_counts(results))
  total = counts.values.sum
  puts
  puts "model-level cases (class A of the case list): #{counts['pass']} of #{total} pass, " \
       "#{counts['fail']} fail, #{counts['error']} error, #{counts['skip']} skip, #{counts['not run']} not run"
end

if (out = ENV.fetch('OUT', nil))
  File.open(out, 'w') do |io|
    results.each do |r|
      r.results.each { |c| io.puts(JSON.generate(c.merge('file' => r.file))) }
      io.puts(JSON.generate('file' => r.file, 'load_error' => r.load_error)) if r.load_error
    end
  end
end
