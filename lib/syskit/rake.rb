# frozen_string_literal: true

require 'rake/testtask'

module Syskit
  # Rake tasks for apps: `require 'syskit/rake'` in an app's Rakefile gives
  # it `rake test`, which runs test/**/test_*.rb with the gem's test harness.
  module RakeTasks
    GEM_LIB = File.expand_path('..', __dir__)

    def self.define_test_task(name = :test)
      ::Rake::TestTask.new(name) do |t|
        t.libs << GEM_LIB << 'test'
        t.test_files = FileList['test/**/test_*.rb']
        t.warning = false
      end
    end
  end
end

unless Rake::Task.task_defined?(:test)
  Syskit::RakeTasks.define_test_task
  task default: :test
end
