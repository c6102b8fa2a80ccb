# frozen_string_literal: true

require_relative 'site_helper'
require_relative 'browser'
require 'uri'

module Syskit
  # The example app's site in a real browser (Debian's chromium, headless):
  # pages load without errors, links lead somewhere, the index's filter
  # works and pages show something. Skipped, saying so, without chromium.
  #
  # SYSKIT_DOC_SCREENSHOTS=DIR keeps a screenshot of each page there, to
  # look at.
  class TestDocSiteInBrowser < Minitest::Test
    include SelfTest::SiteHelper
    extend SelfTest::Long

    # One browser for the tests of this class, closed after the last one
    # (an idle browser left running would slow the timing-sensitive tests
    # that follow).
    def self.browser
      @browser ||= SelfTest::Browser.new.tap { |b| Minitest.after_run { b.close unless b.closed? } }
    end

    def self.test_done
      @done = (@done || 0) + 1
      @browser.close if @browser && !@browser.closed? && @done == runnable_methods.size
    end

    def teardown
      self.class.test_done
    end

    def setup
      skip 'chromium is not installed (apt-get install chromium): the site is not checked in a browser' \
        unless SelfTest::Browser.command
    end

    def browser
      self.class.browser
    end

    def url(path)
      "file://#{File.join(example_site, path)}"
    end

    # Every link of the page, resolved: anchors (HTML and the SVG of the
    # plan), style sheets, scripts.
    LINKS = <<~JS
      [...document.querySelectorAll('a')].map(a =>
        a.href instanceof SVGAnimatedString ? new URL(a.href.baseVal, document.baseURI).href : a.href)
      .concat([...document.querySelectorAll('link[href]')].map(l => l.href))
      .concat([...document.querySelectorAll('script[src]')].map(s => s.src))
    JS

    # A page of each kind (the largest) and the index, whose script is the
    # site's only one: errors, links as the browser resolves them, and a
    # screenshot. Pages of a kind share their template and style, so what
    # only a browser sees differs by kind; every reference of every page is
    # checked without a browser (TestDocSite), as a visit costs chromium
    # about 0.2 s of CPU. With SYSKIT_DOC_SCREENSHOTS, every page is
    # visited, and kept to look at.
    def test_a_page_of_each_kind_loads_without_errors_its_links_resolve_and_it_is_not_blank
      keep = ENV.fetch('SYSKIT_DOC_SCREENSHOTS', nil)
      pages = keep ? html_pages(example_site) : a_page_of_each_kind
      assert_equal %w[. buses compositions devices guides libraries profiles services tasks],
                   pages.map { |path| File.dirname(path) }.uniq.sort
      checked = pages.sum do |path|
        page = browser.open(url(path))
        assert_empty page.errors, "#{path} logged errors"
        refute browser.blank?(page.screenshot(scale: 0.25)), "#{path} looks blank"
        keep_screenshot(page, keep, path) if keep
        links = page.evaluate(LINKS).reject { |link| link.start_with?('data:') }
        links.each { |link| assert_link_resolves(link, path) }.size
      end
      assert_operator checked, :>, 200
    end

    # The check above, on a page that shows nothing and on one that shows
    # a few words.
    def test_a_blank_page_looks_blank_and_a_page_with_words_does_not
      assert browser.blank?(browser.open('data:text/html,<body></body>').screenshot(scale: 0.25))
      2.times { assert browser.blank?(browser.open('about:blank').screenshot(scale: 0.25)) }
      words = browser.open('data:text/html,<p style="font-size:100px">A GPS on a serial line</p>')
      refute browser.blank?(words.screenshot(scale: 0.25))
    end

    def test_the_filter_narrows_the_index
      page = browser.open(url('index.html'))
      all = visible(page)
      entries = 36 + GUIDES.size
      assert_equal entries, all.size
      assert_equal "#{entries} entries", page.evaluate("document.getElementById('search-count').textContent")

      shown = filter(page, 'gps')
      assert_equal %w[awesomerobot::devices::gps::ublox::f9 gps_ublox gps_ublox::f9task], shown
      assert_equal "3 of #{entries}", page.evaluate("document.getElementById('search-count').textContent")
      assert_equal %w[devices libraries tasks], page.evaluate(<<~JS)
        [...document.querySelectorAll('section.kind')].filter(s => s.offsetParent !== null).map(s => s.id)
      JS
      # Every word must match, in the name or the summary.
      assert_equal ['canbus::task'], filter(page, 'canbus per-device')
      assert_empty filter(page, 'no such model')
      assert page.evaluate("document.getElementById('no-match').offsetParent !== null")
      assert_equal all, filter(page, '')
    end

    def test_the_index_opens_filtered_from_its_address
      page = browser.open("#{url('index.html')}#q=temperature")
      assert_equal %w[awesomerobot::devices::temperature::cansensor can_temperature_sensor
                      can_temperature_sensor::task navigation::temperaturemonitor
                      awesomerobot::compositions::temperaturewatch], visible(page)
    end

    def test_slash_focuses_the_filter_and_enter_opens_the_first_match
      page = browser.open(url('index.html'))
      page.evaluate("document.dispatchEvent(new KeyboardEvent('keydown', { key: '/' }))")
      assert_equal 'search', page.evaluate('document.activeElement.id')
      filter(page, 'fluid level')
      page.evaluate("document.getElementById('search').dispatchEvent(new KeyboardEvent('keydown', { key: 'Enter' }))")
      assert_equal url('devices/AwesomeRobot.Devices.N2k.FluidLevel.html'), location_after_navigation(page)
    end

    # The profile's plan is drawn at its own size, wider than the text
    # column if the window allows (it was scaled to the column, its 10 pt
    # text about 7 px high), and the page does not scroll sideways.
    def test_the_plan_is_drawn_at_a_readable_size_without_scrolling_sideways
      skip 'graphviz (dot) is not installed: the drawn plan is not checked' unless Doc.dot_command

      page = browser.open(url('profiles/AwesomeRobot.Profiles.Live.Base.html'))
      scale, overflow, column = page.evaluate(<<~JS)
        (() => { const svg = document.querySelector('figure.graph.plan svg');
                 const html = document.documentElement;
                 return [svg.getBoundingClientRect().width / svg.width.baseVal.value,
                         html.scrollWidth - html.clientWidth, document.querySelector('main p').offsetWidth]; })()
      JS
      # The browser's window is 1,280 px wide: the 991 pt plan is 1,321 px.
      assert_operator scale, :>=, 0.9
      assert_equal 0, overflow
      assert_operator page.evaluate("document.querySelector('figure.graph.plan').offsetWidth"), :>, column
    end

    private

    def a_page_of_each_kind
      html_pages(example_site).group_by { |path| File.dirname(path) }.values.map do |paths|
        paths.max_by { |path| File.size(File.join(example_site, path)) }
      end
    end

    # The page's address once the navigation it started is done.
    def location_after_navigation(page)
      50.times do
        href = begin
          page.evaluate('document.readyState === "complete" && location.href')
        rescue SelfTest::Browser::Error
          nil # the document is being replaced
        end
        return href if href && !href.end_with?('index.html')

        sleep 0.1
      end
      flunk 'the page did not change'
    end

    def keep_screenshot(page, dir, path)
      FileUtils.mkdir_p(dir)
      File.binwrite(File.join(dir, "#{path.tr('/', '_')}.png"), page.screenshot(full: true))
    end

    def visible(page)
      page.evaluate("[...document.querySelectorAll('li[data-name]')].filter(li => li.offsetParent !== null)" \
                    '.map(li => li.dataset.name)')
    end

    def filter(page, text)
      page.evaluate("(() => { const i = document.getElementById('search'); i.value = #{text.to_json}; " \
                    "i.dispatchEvent(new Event('input')); })()")
      visible(page)
    end

    def assert_link_resolves(link, from)
      uri = URI(link)
      assert_equal 'file', uri.scheme, "#{from} links to #{link}"
      path = URI.decode_www_form_component(uri.path)
      assert File.file?(path), "#{from} links to #{link}, which does not exist"
      return unless uri.fragment && !uri.fragment.start_with?('q=')

      assert_includes File.read(path), %(id="#{uri.fragment}"), "#{from} links to #{link}: no such anchor"
    end
  end
end
