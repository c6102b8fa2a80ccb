# frozen_string_literal: true

require 'helper'

module Syskit
  # What a profile assertion of Syskit's harness says when tasks have no
  # deployed task: each task, and the children it is, as Syskit lists them.
  class TestSelfHarnessDeployFailures < Minitest::Test
    parallelize_me!

    DEPLOY_TEST = <<~RUBY
      require 'syskit/test/self'

      describe 'undeployed' do
        it('lists each task without a deployed task and what needs it') do
          task_m = Syskit::TaskContext.new_submodel(name: 'Probe')
          cmp_m = Syskit::Composition.new_submodel(name: 'Survey')
          cmp_m.add task_m, as: 'probe'
          profile = Syskit::Actions::Profile.new('Field')
          profile.define 'survey', cmp_m
          e = assert_raises(Syskit::Test::ProfileAssertions::ProfileAssertionFailed) { assert_can_deploy(profile) }
          assert_match(/Field.survey_def: cannot deploy the following tasks: Probe \\(child probe of Survey\\)/,
                       e.message)
        end
      end
    RUBY

    def test_a_deploy_failure_lists_the_tasks_and_the_children_they_are
      Dir.mktmpdir do |dir|
        path = File.join(dir, 'test', 'test_deploy.rb')
        FileUtils.mkdir_p(File.dirname(path))
        File.write(path, DEPLOY_TEST)
        out, err, = Open3.capture3(SelfTest.child_env, RbConfig.ruby, '-I', File.join(GEM_ROOT, 'lib'),
                                   'test/test_deploy.rb', chdir: dir, unsetenv_others: true)
        assert_match(/1 runs, \d+ assertions, 0 failures, 0 errors, 0 skips/, out, err)
      end
    end
  end
end
