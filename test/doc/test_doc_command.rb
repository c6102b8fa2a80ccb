# frozen_string_literal: true

require_relative 'site_helper'

module Syskit
  # `syskit doc` where things go wrong, and the site's pages for what the
  # example app does not show.
  class TestDocCommand < Minitest::Test
    extend SelfTest::Long
    include SelfTest::SiteHelper

    def teardown
      (@tmpdirs || []).each { |d| FileUtils.rm_rf(d) }
      (@loaded_apps || []).each(&:unload)
    end

    def output_dir
      dir = Dir.mktmpdir('syskit-doc')
      (@tmpdirs ||= []) << dir
      File.join(dir, 'site')
    end

    def test_the_site_goes_to_doc_site_in_the_app_by_default
      root = my_app("device MyApp::Devices::IMU, as: 'imu'")
      out, err, status = run_cli('doc', '--app', root)
      assert_equal [0, ''], [status, err]
      pages = 12 + GUIDES.size # the index, the app's 11 entries and the guides
      assert_equal "wrote #{pages} pages to #{root}/doc/site\nopen #{root}/doc/site/index.html\n", out
      assert File.file?(File.join(root, 'doc', 'site', 'profiles', 'MyApp.Profiles.Base.html'))
    end

    def test_a_loading_error_is_reported_and_nothing_is_written
      root = my_app("device MyApp::Devices::IMU, as: 'imu'\ndevice MyApp::Devices::Nope, as: 'x'")
      output = output_dir
      out, err, status = run_cli('doc', '--app', root, '--output', output)
      assert_equal [1, ''], [status, out]
      assert_match(%r{\Amodels/profiles/base\.rb:10: .*Nope}, err)
      refute File.exist?(output)
      assert_empty Dir.children(File.dirname(output)), 'no staging directory is left behind'
    end

    def test_an_unknown_robot_is_an_error
      _, err, status = run_cli('doc', '--app', EXAMPLE, '--robot', 'nope', '--output', output_dir)
      assert_equal 1, status
      assert_equal "config/robots/nope.rb: no configuration for robot 'nope'\n  hint: create config/robots/nope.rb " \
                   "with Syskit.conf.use_deployment statements\n", err
    end

    def test_a_directory_that_is_not_a_site_is_never_replaced
      output = output_dir
      FileUtils.mkdir_p(output)
      File.write(File.join(output, 'notes.txt'), 'mine')
      out, err, status = run_cli('doc', '--app', EXAMPLE, '--output', output)
      assert_equal [1, ''], [status, out]
      assert_equal "cannot write the site into #{output}: it is a directory that is not a site written by syskit " \
                   "doc\n  hint: give another --output, or remove it first\n", err
      assert_equal ['notes.txt'], Dir.children(output)

      file = File.join(File.dirname(output), 'file')
      File.write(file, '')
      _, err, = run_cli('doc', '--app', EXAMPLE, '--output', file)
      assert_match(/cannot write the site into #{Regexp.escape(file)}: it is a file/, err)
    end

    def test_a_site_written_before_is_replaced_whole
      root = my_app("device MyApp::Devices::IMU, as: 'imu'")
      output = output_dir
      assert_equal 0, run_cli('doc', '--app', root, '--output', output)[2]
      File.write(File.join(output, 'devices', 'Stale.html'), 'from an older model')
      _, err, status = run_cli('doc', '--app', root, '--output', output)
      assert_equal [0, ''], [status, err]
      refute File.exist?(File.join(output, 'devices', 'Stale.html'))
      assert_equal ['site'], Dir.children(File.dirname(output))
    end

    def test_a_profile_that_cannot_be_planned_says_why_on_its_page
      root = my_app("device MyApp::Devices::IMU, as: 'imu'\ndevice MyApp::Devices::TemperatureSensor, as: 't'")
      output = output_dir
      _, err, status = run_cli('doc', '--app', root, '--output', output)
      assert_equal 0, status
      assert_match(/\AMyApp::Profiles::Base could not be planned \(no deployed task .*\): its page says why\n\z/, err)
      doc = page('profiles/MyApp.Profiles.Base.html', output)
      error = texts(doc, "//div[@class='error']//li").first
      assert_match(%r{\Amodels/profiles/base\.rb:10 no deployed task}, error)
      assert_match(/hint: /, error)
      assert_empty REXML::XPath.match(doc, "//section[@id='tasks']")
    end

    # Definitions are alternatives (examples/arm_lab has two for the same
    # arm, and a generic profile leaving a tag to another): when each
    # plans on its own, the page shows the devices' plan and says why.
    def test_definitions_that_cannot_run_together_are_planned_apart
      output = output_dir
      _, err, status = run_cli('doc', '--app', File.join(GEM_ROOT, 'examples', 'arm_lab'), '--output', output)
      assert_equal [0, ''], [status, err]
      doc = page('profiles/ArmLab.Profiles.Bench.html', output)
      assert_empty REXML::XPath.match(doc, "//div[@class='error']")
      assert_match(/\AThis is the plan of its devices: its definitions cannot all be planned with them \(.*/,
                   texts(doc, "//section[@id='plan']/p[@class='notice']").first)
      assert_equal %w[left_arm right_arm wand], texts(doc, "//section[@id='tasks']/table[1]/tbody/tr/td[1]")
      lab = page('profiles/ArmLab.Profiles.Lab.html', output)
      assert_match(/those using its tags in the profiles that select them\.\z/,
                   texts(lab, "//section[@id='plan']/p[@class='notice']").first)
    end

    def test_without_graphviz_the_profile_page_says_how_to_get_it
      app = load_app(EXAMPLE, robots: ['default'], everything: true)
      output = output_dir
      result = Doc.build(app, output: output, dot: nil)
      assert_nil result.dot
      doc = page('profiles/AwesomeRobot.Profiles.Live.Base.html', output)
      assert_match(/drawn by Graphviz, which is not installed here: install it \(sudo apt install graphviz/,
                   texts(doc, "//section[@id='plan']/p[@class='notice']").first)
      assert_equal 14, REXML::XPath.match(doc, "//section[@id='tasks']/table[1]/tbody/tr").size
    end

    def test_models_of_other_bundles_are_marked_with_their_bundle
      output = output_dir
      _, err, status = run_cli('doc', '--app', fixture('rock', 'rover'), '--output', output)
      assert_equal 0, status
      assert_match(/^\d+ warnings while loading \(syskit check lists them\)$/, err)
      lidar = REXML::XPath.first(page('index.html', output), "//li[@data-name='baseparts::devices::lidar']")
      assert_equal 'base_parts', texts(lidar, ".//span[@class='badge origin']").first
    end

    def test_the_command_has_help
      out, = run_cli('help', 'doc')
      assert_match(%r{\[--output=OUTPUT\] +# where to write the site \(default: doc/site in the app\)}, out)
      assert_match(/^  syskit doc +# write the app's models/, run_cli('help').first)
    end
  end
end
