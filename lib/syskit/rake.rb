# frozen_string_literal: true

require 'rake'
require 'shellwords'
require 'syskit/test/runner'

module Syskit
  # Rake tasks for apps: `require 'syskit/rake'` in an app's Rakefile gives
  # it `rake test`, which runs test/**/test_*.rb as `syskit test` does
  # (TEST=file runs one file, TESTOPTS passes options to minitest).
  module RakeTasks
    def self.define_test_task(name = :test)
      Rake.application.last_description = "run the app's tests with syskit's test harness"
      Rake::Task.define_task(name) do
        root = Rake.application.original_dir
        files = ENV['TEST'] ? [ENV['TEST']] : []
        options = Shellwords.split(ENV.fetch('TESTOPTS', ''))
        Test::Runner.run(root, Test::Runner.test_files(root, files, pwd: root), Test::Runner.parse(options).minitest)
      rescue Syskit::Error => e
        warn e.report(root)
        exit 1
      end
    end
  end
end

unless Rake::Task.task_defined?(:test)
  Syskit::RakeTasks.define_test_task
  Rake::Task.define_task(default: :test)
end
