# frozen_string_literal: true

require_relative 'site_helper'
require 'uri'

module Syskit
  # `syskit doc` on the example app and on small apps, read from the files
  # it writes (the browser tests are in test_site_in_browser.rb).
  class TestDocSite < Minitest::Test
    extend SelfTest::Long
    include SelfTest::SiteHelper

    def test_it_prints_where_the_site_is
      out = SelfTest::SiteHelper.example_site { flunk }.last if example_site
      dir = example_site
      assert_equal "wrote #{html_pages(dir).size} pages to #{dir}\nopen #{dir}/index.html\n", out
    end

    # The count the site guide shows is the example site's.
    def test_the_site_guide_shows_what_the_command_prints
      shown = SelfTest::Docs.guide('site').output_of('bundle exec bin/syskit doc --app examples/awesome_robot ' \
                                                     '--output /tmp/site')
      assert_equal "wrote #{html_pages(example_site).size} pages to /tmp/site\nopen /tmp/site/index.html\n", shown
    end

    def test_the_index_lists_every_kind_and_marks_what_comes_from_a_bundle
      index = page('index.html')
      assert_equal ['Device models 7', 'Bus models 2', 'Data services 1', 'Task libraries 10', 'Task models 13',
                    'Compositions 2', 'Profiles 1', "Guides #{GUIDES.size}"], texts(index, '//section/h2')
      can = REXML::XPath.first(index, "//li[@data-name='commonmodels::devices::bus::can']")
      assert_equal "CommonModels::Devices::Bus::CAN common_models (syskit's own) Controller Area Network.", squeeze(can)
      f9 = REXML::XPath.first(index, "//li[@data-name='awesomerobot::devices::gps::ublox::f9']")
      assert_equal 'devices/AwesomeRobot.Devices.GPS.Ublox.F9.html', REXML::XPath.first(f9, 'a').attributes['href']
      assert_nil REXML::XPath.first(f9, ".//span[@class='badge origin']")
    end

    # Each guide is a page, listed last on the index in the order of the
    # README's "Where to read on", with its line there.
    def test_every_guide_is_a_page_listed_on_the_index
      read_on = SelfTest::Docs.readme.section('Where to read on').links.map(&:first)
                              .grep(%r{\Adoc/guides/}).map { |l| File.basename(l, '.md') }
      assert_equal GUIDES, read_on.sort, "the README's Where to read on lists every guide, once"
      items = REXML::XPath.match(page('index.html'), "//section[@id='guides']/ul/li")
      assert_equal(read_on.map { |name| "guides/#{name}.html" }, items.map { |li| li.elements['a'].attributes['href'] })
      assert_equal 'Devices, buses and drivers model files, configuration files, configure methods and stubs, ' \
                   'and the API, one line per call.', squeeze(items.first)
      GUIDES.each { |name| assert_guide_page(name) }
    end

    # The page of a guide: its title, and where it is.
    def assert_guide_page(name)
      title = SelfTest::Docs.guide(name).headings.first[1]
      guide = page("guides/#{name}.html")
      assert_equal Doc::Markdown.plain(title), texts(guide, '//article/h1').first, name
      assert_equal %w[AwesomeRobot Guides Guides], texts(guide, '//header/a | //header/span')
    end

    # Links between guides lead to their pages and anchors; links to files
    # the site does not have (the README, the code) are their text alone.
    def test_the_links_of_the_guide_pages_resolve_in_the_site
      dir = example_site
      checked = 0
      GUIDES.each do |name|
        REXML::XPath.match(page("guides/#{name}.html"), '//main//a/@href').map(&:value).each do |href|
          path, anchor = href.split('#', 2)
          target = path.empty? ? "guides/#{name}.html" : File.join('guides', path)
          assert File.file?(File.join(dir, target)), "guides/#{name}.html links to #{href}: no such page"
          ids = REXML::XPath.match(page(target), '//@id').map(&:value)
          assert_includes ids, anchor, "guides/#{name}.html links to #{href}" if anchor
          checked += 1
        end
      end
      assert_operator checked, :>=, 10
      compositions = page('guides/compositions.html')
      assert_match(/\AA composition puts components together .* as the README's tour shows/,
                   texts(compositions, '//article/p').first)
      assert_equal ['The plan', 'Testing an app'], texts(compositions, '//article/p[1]/a')
    end

    def test_every_page_is_well_formed_with_unique_ids_and_no_external_resource
      dir = example_site
      html_pages(dir).each do |path|
        text = File.read(File.join(dir, path))
        assert text.start_with?("<!DOCTYPE html>\n<html lang=\"en\">"), path
        doc = page(path, dir) # raises on anything that is not well-formed
        ids = REXML::XPath.match(doc, '//@id').map(&:value)
        assert_equal ids.uniq, ids, "#{path}: duplicate ids"
        refute_empty texts(doc, '/html/head/title').first, path
        refs = REXML::XPath.match(doc, '//@href | //@src | //@xlink:href').map(&:value)
        assert_empty refs.grep(%r{\A(?:[a-z]+:)?//}i), "#{path} refers to the network"
      end
    end

    # Every link, style sheet and script of every page (anchors of the HTML
    # and of the plan's SVG) leads to a file of the site, and to an id of
    # that page when it names one. The browser test visits a page of each
    # kind; this one reads them all.
    def test_every_reference_of_every_page_resolves_in_the_site
      dir = example_site
      ids = Hash.new { |known, target| known[target] = REXML::XPath.match(page(target, dir), '//@id').map(&:value) }
      checked = html_pages(dir).sum do |path|
        refs = REXML::XPath.match(page(path, dir), '//@href | //@src | //@xlink:href').map(&:value)
        refs.reject { |ref| ref.start_with?('data:') }.each { |ref| assert_resolves(ref, path, dir, ids) }.size
      end
      assert_operator checked, :>, 300
    end

    def test_the_same_app_gives_the_same_bytes
      again = File.join(Dir.mktmpdir('syskit-doc'), 'site')
      _, err, status = run_cli('doc', '--app', SelfTest::SiteHelper::EXAMPLE, '--output', again)
      assert_equal 0, status, err
      assert_equal site_files(example_site), site_files(again)
      site_files(again).each do |file|
        assert File.binread(File.join(example_site, file)) == File.binread(File.join(again, file)), "#{file} differs"
      end
    ensure
      FileUtils.rm_rf(File.dirname(again))
    end

    def test_a_device_model_page
      doc = page('devices/AwesomeRobot.Devices.GPS.Ublox.F9.html')
      assert_equal ["Ublox's 9th generation GNSS receivers (F9P, F9R)."], texts(doc, "//div[@class='doc']/p")
      assert_equal ['pose_samples output /base/samples/RigidBodyState'], texts(doc, "//section[@id='ports']//tbody/tr")
      assert_equal ['AwesomeRobot::Services::Position, ports mapped: position_samples → pose_samples'],
                   texts(doc, "//section[@id='provides']//li")
      assert_equal ['gps_ublox::F9Task f9 (AwesomeRobot::Devices::GPS::Ublox::F9) pose_samples'],
                   texts(doc, "//section[@id='drivers']//tbody/tr")
      assert_equal ['gps in AwesomeRobot::Profiles::Live::Base'], texts(doc, "//section[@id='robots']//li")
      assert_equal '../tasks/gps_ublox.F9Task.html',
                   REXML::XPath.first(doc, "//section[@id='drivers']//a").attributes['href']
    end

    def test_a_data_service_page_says_what_provides_it
      doc = page('services/AwesomeRobot.Services.Position.html')
      assert_equal ['Provided by AwesomeRobot::Devices::GPS::Ublox::F9.'],
                   texts(doc, "//section[@id='provides']/p")
      assert_equal ['gps_ublox::F9Task f9 (AwesomeRobot::Devices::GPS::Ublox::F9) pose_samples'],
                   texts(doc, "//section[@id='drivers']//tbody/tr")
    end

    def test_a_bus_model_page
      doc = page('buses/CommonModels.Devices.Bus.CAN.html')
      facts = texts(doc, "//section[@id='bus']/dl/*")
      assert_equal ['message type', '/canbus/Message'], facts.first(2)
      assert_equal ['attached devices get', '.can_id'], facts.last(2)
      assert_includes texts(doc, "//section[@id='bus']//tbody/tr"), 'BusInSrv to_bus input the bus driver'
      uses = texts(doc, "//section[@id='robots']//li")
      assert_equal 'can0 in AwesomeRobot::Profiles::Live::Base, attached devices: temperature_sensor ' \
                   '(AwesomeRobot::Devices::Temperature::CANSensor), water_temperature ' \
                   '(AwesomeRobot::Devices::Temperature::CANSensor), sync (AwesomeRobot::Devices::CANOpenSync), ' \
                   'n2k (AwesomeRobot::Devices::N2k::Bus)', uses.first
      assert_equal 3, uses.size # can0, n2k (a CAN bus through its provides), can1
      # simple_can::Task drives CAN buses through BusSrv, nmea2000::CANTask its sub-bus.
      assert_equal %w[canbus::Task nmea2000::CANTask simple_can::Task],
                   texts(doc, "//section[@id='drivers']//td[1]").uniq
    end

    def test_a_task_model_page_with_its_configuration_sections
      doc = page('tasks/camera_gige.Task.html')
      assert_equal ['GigE Vision camera driver.'], texts(doc, "//div[@class='doc']/p")
      assert_equal ['exposure /int32_t 10000', 'frame_rate /double 10.0', 'ip /std/string none'],
                   texts(doc, "//section[@id='properties']//tbody/tr")
      assert_equal %w[default forward aft], texts(doc, "//section[@id='configuration']/h3")
      assert_equal ['exposure 5000', 'frame_rate 20.0'],
                   texts(doc, "//section[@id='configuration']/table[1]//tr")
      assert_equal ['ip "10.40.50.50"'], texts(doc, "//section[@id='configuration']/table[2]//tr")
      assert_equal ['aft_camera in deployment cameras of camera_gige, on robot default',
                    'forward_camera in deployment cameras of camera_gige, on robot default'],
                   texts(doc, "//section[@id='deployments']//li")
      assert_equal ['forward_camera in AwesomeRobot::Profiles::Live::Base',
                    'aft_camera in AwesomeRobot::Profiles::Live::Base'], texts(doc, "//section[@id='robots']//li")
    end

    def test_a_task_model_page_shows_inheritance_dynamic_ports_and_operations
      doc = page('tasks/canbus.Task.html')
      assert_includes texts(doc, "//section[@id='services']//tbody/tr"),
                      'bus_in CommonModels::Devices::Bus::CAN::BusInSrv provides ' \
                      '(drives CommonModels::Devices::Bus::CAN, argument bus_in_dev) to_bus → in'
      assert_includes texts(doc, "//section[@id='ports']/table[2]//tr"), '/\\w+/ output /canbus/Message'
      assert_match(/\Awatch\(name: /, texts(doc, "//section[@id='operations']//tbody/tr").last)
      gps = page('tasks/gps_ublox.F9Task.html')
      assert_equal ['task library', 'gps_ublox', 'subclass of', 'iodrivers_base::Task'],
                   texts(gps, "//dl[@class='facts']/*").first(4)
      inherited = texts(gps, "//section[@id='properties']//tbody/tr/td[1]").grep(/from/)
      assert_includes inherited, 'io_port from iodrivers_base::Task'
    end

    # A port declared with a typedef's name shows that name, and the type
    # it stands for beside it.
    def test_a_port_declared_with_a_typedef_shows_its_declared_name
      dir = File.join(Dir.mktmpdir('syskit-doc'), 'site')
      (@tmpdirs ||= []) << File.dirname(dir)
      _, err, status = run_cli('doc', '--app', File.join(GEM_ROOT, 'examples', 'arm_lab'), '--output', dir)
      assert_equal 0, status, err
      rows = texts(page(Dir.glob('**/*JointsCommand.html', base: dir).first, dir), "//section[@id='ports']//tr")
      assert_includes rows, 'command_in input /base/commands/Joints = /base/samples/Joints'
    end

    def test_a_profile_page
      doc = page('profiles/AwesomeRobot.Profiles.Live.Base.html')
      devices = texts(doc, "//section[@id='devices']//tbody/tr[@id]")
      assert_equal 12, devices.size
      # The comment above a device's declaration is its documentation, in the row after it.
      assert_equal 'Its frames travel on can0\'s wire.',
                   texts(doc, "//tr[@id='device-fuel_level']/following-sibling::tr[1][@class='device-doc']").first
      assert_equal 'temperature_sensor AwesomeRobot::Devices::Temperature::CANSensor can_temperature_sensor::Task ' \
                   'can0 can_id [0x1234,0xFFFF] prefer_deployed_tasks "temperature_sensor" period 100 ms frame 1 frame',
                   devices.grep(/\Atemperature_sensor/).first
      assert_equal 14, REXML::XPath.match(doc, "//section[@id='tasks']/table[1]/tbody/tr").size
      assert_includes texts(doc, "//section[@id='tasks']/table[2]//tr"),
                      'can0.temperature_sensor temperature_sensor.can_in /canbus/Message buffer 2'
      assert_equal ['Bus can0', 'Bus can1'], texts(doc, "//section[@class='can-bus']/h2")
      timing = texts(doc, "//section[@id='bus-can1']//table[@class='timing']/tbody/tr")
      assert_equal '202 right_motor 8 1.000 1.000 0.200 0.135 0.065 0.805 0.195 ok', timing[3]
    end

    def test_a_profile_page_lists_its_definitions
      doc = page('profiles/AwesomeRobot.Profiles.Live.Base.html')
      rows = texts(doc, "//section[@id='definitions']//tbody/tr[@id]")
      assert_equal ['drive_def AwesomeRobot::Compositions::Drive position gps_dev left left_motor_dev right ' \
                    'right_motor_dev arguments max_speed: 0.5',
                    'watch_temperatures_def AwesomeRobot::Compositions::TemperatureWatch engine ' \
                    'temperature_sensor_dev water water_temperature_dev sections summer'], rows
      assert_equal 'Follows the path with the GPS pose, at half speed.',
                   texts(doc, "//tr[@id='definition-drive']/following-sibling::tr[1]").first
      link = REXML::XPath.first(doc, "//tr[@id='definition-drive']//a[code='gps_dev']")
      assert_equal '#device-gps', link.attributes['href']
    end

    def test_a_composition_page
      doc = page('compositions/AwesomeRobot.Compositions.Drive.html')
      assert_match(/\ADrives the robot along its path/, texts(doc, "//div[@class='doc']/p").first)
      assert_equal ['position AwesomeRobot::Services::Position to select',
                    'follower navigation::PathFollower arguments max_speed: from(:parent_task).max_speed',
                    'left AwesomeRobot::Devices::Roboteq::CANOpen to select',
                    'right AwesomeRobot::Devices::Roboteq::CANOpen to select'],
                   texts(doc, "//section[@id='children']//tbody/tr")
      assert_equal ['position.position_samples follower.pose data', 'follower.left_speed left.speed_command data',
                    'follower.right_speed right.speed_command data'],
                   texts(doc, "//section[@id='dataflow']//table[@class='connections']/tbody/tr")
      assert_equal ['pose input /base/samples/RigidBodyState follower.pose'],
                   texts(doc, "//section[@id='ports']//tbody/tr")
      assert_equal ['AwesomeRobot::Profiles::Live::Base.drive_def'], texts(doc, "//section[@id='definitions']//li")
      %w[dataflow hierarchy].each do |graph|
        refute_nil REXML::XPath.first(doc, "//section[@id='#{graph}']//*[local-name()='svg']"), graph
      end
      watch = page('compositions/AwesomeRobot.Compositions.TemperatureWatch.html')
      assert_equal ['summer: monitor with default, summer'], texts(watch, "//section[@id='ports']/ul/li")
    end

    def test_the_profile_page_draws_the_plan_with_links_to_the_task_models
      skip 'graphviz (dot) is not installed: the drawn plan is not checked' unless Doc.dot_command
      html = File.read(File.join(example_site, 'profiles/AwesomeRobot.Profiles.Live.Base.html'))
      svg = html[%r{<figure class="graph plan">\s*(<svg.*?</svg>)}m, 1]
      refute_nil svg, 'the plan is drawn inline'
      assert_includes svg, %(xlink:href="../tasks/canbus.Task.html")
      assert_includes svg, '>left_motor</text>'
    end

    def test_each_can_bus_has_its_charts
      html = File.read(File.join(example_site, 'profiles/AwesomeRobot.Profiles.Live.Base.html'))
      can1 = html[%r{<section id="bus-can1".*?</section>}m]
      assert_equal 2, can1.scan('<svg class="chart"').size
      assert_includes can1, '<text class="label" x="218" y="78">left_motor  27.1 %</text>'
      assert_includes can1, '0.805 / 1 ms</text>'
    end

    private

    # +ref+, on the page at +path+, names a file of the site in +dir+ and,
    # with an anchor, an id of that page (+ids+: a page's ids by path).
    # The index's anchors are its filter (#q=...).
    def assert_resolves(ref, path, dir, ids)
      file, anchor = URI::DEFAULT_PARSER.unescape(ref).split('#', 2)
      target = file.empty? ? path : File.expand_path(file, "/#{File.dirname(path)}").delete_prefix('/')
      assert File.file?(File.join(dir, target)), "#{path} refers to #{ref}, which does not exist"
      return unless anchor && target.end_with?('.html') && !anchor.start_with?('q=')

      assert_includes ids[target], anchor, "#{path} refers to #{ref}: no such anchor"
    end
  end
end
