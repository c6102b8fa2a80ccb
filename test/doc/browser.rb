# frozen_string_literal: true

require 'json'
require 'tmpdir'
require 'fileutils'
require 'base64'
require 'timeout'
require 'io/nonblock'

module Syskit
  module SelfTest
    # Debian's chromium, headless, driven through the DevTools protocol
    # over a pipe (--remote-debugging-pipe: commands on the browser's fd 3,
    # answers and events on its fd 4, each message JSON ending with a NUL
    # byte). The standard library is enough for that; no websocket, no gem.
    class Browser
      class Error < StandardError; end

      # The events that are errors of a page, and what to say of each
      # (nil: not an error).
      ERROR_EVENTS = {
        'Runtime.exceptionThrown' => lambda { |p|
          p.dig('exceptionDetails', 'exception', 'description') || p['exceptionDetails']['text']
        },
        'Runtime.consoleAPICalled' => lambda { |p|
          "console.#{p['type']}: #{p['args'].map { |a| a['value'] }.join(' ')}" if %w[error assert].include?(p['type'])
        },
        'Log.entryAdded' => ->(p) { "#{p['entry']['text']} #{p['entry']['url']}" if p['entry']['level'] == 'error' }
      }.freeze

      COMMANDS = %w[chromium chromium-browser google-chrome].freeze
      TIMEOUT = 30

      # The browser's executable on PATH, or nil.
      def self.command
        ENV.fetch('PATH', '').split(File::PATH_SEPARATOR).product(COMMANDS)
           .map { |dir, name| File.join(dir, name) }.find { |p| File.file?(p) && File.executable?(p) }
      end

      # A page loaded in the browser: what it logged, and a handle to run
      # scripts in it and take screenshots.
      Page = Struct.new(:browser, :session, :url, :errors) do
        def evaluate(expression)
          browser.evaluate(session, expression)
        end

        # A PNG of the viewport (of the whole page with +full+), scaled by
        # +scale+.
        def screenshot(scale: 1, full: false)
          browser.screenshot(session, scale, full)
        end

        # A PNG of the element +selector+ finds.
        def element_screenshot(selector, scale: 1)
          box = evaluate("(() => { const r = document.querySelector(#{selector.to_json}).getBoundingClientRect(); " \
                         'return { x: r.x + scrollX, y: r.y + scrollY, width: r.width, height: r.height }; })()')
          browser.screenshot(session, scale, true, box.transform_keys(&:to_sym))
        end
      end

      def initialize(width: 1280, height: 900)
        @profile = Dir.mktmpdir('syskit-chromium')
        to_browser, @commands = IO.pipe
        @events, from_browser = IO.pipe
        # Ruby makes its pipes non-blocking, a flag the browser's ends
        # share: chromium would take EAGAIN for the end of the connection.
        [to_browser, from_browser].each { |io| io.nonblock = false }
        args = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--no-first-run',
                '--no-default-browser-check', '--disable-extensions', '--mute-audio', '--hide-scrollbars',
                '--force-color-profile=srgb', "--window-size=#{width},#{height}", "--user-data-dir=#{@profile}",
                '--remote-debugging-pipe', 'about:blank']
        # CHROME_BIN: another browser; BROWSER_LOG: a file for its messages.
        @pid = Process.spawn(ENV['CHROME_BIN'] || self.class.command, *args,
                             3 => to_browser, 4 => from_browser,
                             in: File::NULL, out: File::NULL, err: ENV['BROWSER_LOG'] || File::NULL)
        to_browser.close
        from_browser.close
        @next_id = 0
        @pending = []
        @buffer = +''
      end

      # Opens +url+ (in the browser's one tab) and waits until it is
      # loaded; the page's errors (exceptions, console.error, failed
      # loads) are collected.
      #
      # The page shown before is marked, and the new one is loaded when
      # the document has no mark and is complete: load events can be stale
      # (a page a test navigated to by a click).
      def open(url)
        session = tab
        # Another fragment of the page shown would not load it again (an
        # empty page always loads a new document).
        shown = evaluate(session, "location.href.split('#')[0]")
        open('about:blank') if url != 'about:blank' && shown == url.split('#').first
        evaluate(session, 'window.syskitPrevious = true')
        collect_errors(session, []) # the previous page's
        command('Page.navigate', { url: url }, session: session)
        wait_until_loaded(session)
        errors = []
        collect_errors(session, errors)
        Page.new(self, session, url, errors)
      end

      def wait_until_loaded(session)
        Timeout.timeout(TIMEOUT) do
          loop do
            loaded = begin
              evaluate(session, "!window.syskitPrevious && document.readyState === 'complete'")
            rescue Error
              false # the document is being replaced
            end
            break if loaded

            sleep 0.02
          end
        end
        @pending.reject! { |m| m['method'] == 'Page.loadEventFired' }
      end

      def tab
        @tab ||= begin
          target = command('Target.createTarget', { url: 'about:blank' })['targetId']
          session = command('Target.attachToTarget', { targetId: target, flatten: true })['sessionId']
          %w[Page.enable Runtime.enable Log.enable].each { |m| command(m, session: session) }
          session
        end
      end

      def evaluate(session, expression)
        result = command('Runtime.evaluate', { expression: expression, returnByValue: true, awaitPromise: true },
                         session: session)
        raise Error, "#{expression}: #{result['exceptionDetails']}" if result['exceptionDetails']

        result.dig('result', 'value')
      end

      def screenshot(session, scale, full, clip = nil)
        metrics = command('Page.getLayoutMetrics', session: session)
        viewport = metrics['cssLayoutViewport']
        height = full ? metrics['cssContentSize']['height'] : viewport['clientHeight']
        clip ||= { x: 0, y: 0, width: viewport['clientWidth'], height: height }
        clip = clip.merge(scale: scale)
        params = { format: 'png', clip: clip, captureBeyondViewport: full }
        Base64.decode64(command('Page.captureScreenshot', params, session: session)['data'])
      end

      def closed?
        @closed
      end

      def close
        @closed = true
        begin
          Timeout.timeout(5) { command('Browser.close') }
        rescue StandardError, Timeout::Error
          nil
        end
        begin
          Timeout.timeout(5) { Process.wait(@pid) }
        rescue Timeout::Error
          Process.kill('KILL', @pid)
          Process.wait(@pid)
        end
        [@commands, @events].each(&:close)
        FileUtils.rm_rf(@profile)
      end

      # Whether +png+ (a screenshot) shows something: more than 1 % of its
      # pixels differ from its most common colour. The browser decodes it,
      # in the tab (on a canvas the page does not show).
      def blank?(png)
        pixels, most_common = evaluate(tab, <<~JS)
          (async () => {
            const image = new Image();
            image.src = 'data:image/png;base64,#{Base64.strict_encode64(png)}';
            await image.decode();
            const canvas = document.createElement('canvas');
            canvas.width = image.width;
            canvas.height = image.height;
            const context = canvas.getContext('2d');
            context.drawImage(image, 0, 0);
            const data = context.getImageData(0, 0, image.width, image.height).data;
            const counts = new Map();
            let most = 0;
            for (let i = 0; i < data.length; i += 4) {
              const colour = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
              const count = (counts.get(colour) || 0) + 1;
              counts.set(colour, count);
              if (count > most) most = count;
            }
            return [data.length / 4, most];
          })()
        JS
        (pixels - most_common) < pixels / 100
      end

      private

      def command(method, params = {}, session: nil)
        id = (@next_id += 1)
        message = { id: id, method: method, params: params }
        message[:sessionId] = session if session
        @commands.write(JSON.generate(message), "\0")
        @commands.flush
        reply = read_until { |m| m['id'] == id }
        raise Error, "#{method}: #{reply['error']['message']}" if reply['error']

        reply['result']
      end

      # Events read while waiting for an answer are kept for later.
      def read_until(&wanted)
        found = @pending.find(&wanted)
        return @pending.delete(found) if found

        Timeout.timeout(TIMEOUT) do
          loop do
            message = next_message
            return message if wanted.call(message)

            @pending << message
          end
        end
      end

      def next_message
        until (at = @buffer.index("\0"))
          chunk = @events.readpartial(1 << 16)
          @buffer << chunk
        end
        text = @buffer.slice!(0..at).chop
        JSON.parse(text)
      end

      def collect_errors(session, errors)
        @pending.reject! do |m|
          next false unless m['sessionId'] == session && ERROR_EVENTS.key?(m['method'])

          error = ERROR_EVENTS[m['method']].call(m['params'])
          errors << error if error
          true
        end
      end
    end
  end
end
