# frozen_string_literal: true

require 'helper'
require 'generators/gen_test_helpers'

module Syskit
  # What generated files leave to git and to the site.
  class TestGenFiles < Minitest::Test
    include GenTestHelpers

    # The generated models' placeholders (TODO paragraphs) are not shown
    # as documentation on the site; what replaces them is.
    def test_the_site_leaves_out_the_generated_placeholders
      app, = new_app
      gen('dev', 'gps/ublox/f9', chdir: app)
      _, err, status = run_cli('doc', '--app', app)
      assert_equal 0, status, err
      page = File.read(File.join(app, 'doc', 'site', 'devices', 'AwesomeRobot.Devices.GPS.Ublox.F9.html'))
      refute_includes page, 'TODO'
      assert_includes page, 'Its driver declares that it drives it'
      device = File.join(app, 'models', 'devices', 'gps', 'ublox', 'f9.rb')
      File.write(device,
                 File.read(device).sub(/# TODO: .*?after its driver\.\n/m, "# The GNSS receiver of the rover.\n"))
      run_cli('doc', '--app', app)
      page = File.read(File.join(app, 'doc', 'site', 'devices', 'AwesomeRobot.Devices.GPS.Ublox.F9.html'))
      assert_includes page, '<p>The GNSS receiver of the rover.</p>'
    end

    # What git should not track in an app: Bundler's files of this machine,
    # and the site syskit doc writes.
    def test_a_new_app_has_a_gitignore
      app, = new_app
      ignored = File.readlines(File.join(app, '.gitignore'), chomp: true).grep_v(/\A#/)
      assert_equal %w[/.bundle/ /vendor/bundle/ /Gemfile.lock /tmp/ /doc/site/], ignored
    end
  end
end
