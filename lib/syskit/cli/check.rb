# frozen_string_literal: true

module Syskit
  # `syskit check`, a command of `syskit` (see syskit/cli.rb): every problem
  # of an app, as text grouped by file or as JSON.
  class CLI < Thor
    desc 'check', 'load an app, generate every profile on the robots that load it, report every problem'
    long_desc <<~TEXT
      Reports all the problems found (not only the first), grouped by file,
      and exits with status 1 if there is any error. Overlapping CAN filters
      are warnings; --strict makes them errors.

      Example: syskit check --app ~/dev/awesome_robot --format json
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    method_option :strict, type: :boolean, default: false, desc: 'treat warnings as errors'
    method_option :format, type: :string, default: 'text', enum: %w[text json], desc: 'output format'
    def check
      with_app(load: false) do |app|
        report = Check.new(app).run
        report.strict! if options[:strict]
        print_check(app, report)
        exit(1) if report.errors.any?
      end
    end

    private

    def print_check(app, report)
      return print_check_json(app, report) if options[:format] == 'json'

      # Files in the order their first problem was found, which puts the
      # cause before what follows from it; lines in order within a file.
      groups = report.problems.group_by { |p| p.location&.relative_path(app.root).to_s }
      hints = Set.new
      groups.each_with_index do |(_file, problems), i|
        puts if i.positive?
        print_problems(app, problems, hints)
      end
      puts "#{app.name}: #{report.errors.size} error(s), #{report.warnings.size} warning(s)"
    end

    # The problems of one file, in line order. A warning's hint is given
    # once, under the first warning of its kind (+hints+: those given).
    def print_problems(app, problems, hints)
      style = Style.for($stdout)
      problems.sort_by { |p| p.location&.lineno.to_i }.each do |p|
        p = p.without_hint if p.is_a?(Warning) && p.hint && !hints.add?(p.hint)
        puts style.report(p, app.root)
        puts((p.backtrace || []).map { |l| "    #{l}" }) if trace?
      end
    end

    def print_check_json(app, report)
      require_once 'json'
      puts ::JSON.pretty_generate('app' => app.name, 'errors' => report.errors.size,
                                  'warnings' => report.warnings.size,
                                  'problems' => report.problems.map { |p| p.to_h(app.root) })
    end
  end
end
