# frozen_string_literal: true

require 'helper'
require 'socket'
require 'syskit/bus/monitor'
require 'syskit/bus/dispatcher'

module Syskit
  module Bus
    # Reading frame records from IOs, and the live monitor, end to end over
    # UNIX socket pairs carrying raw can_frame/canfd_frame bytes (and over a
    # vcan interface when the machine has one).
    class TestMonitor < Minitest::Test
      EXAMPLE = File.join(GEM_ROOT, 'examples', 'awesome_robot')

      def setup
        super
        @sockets = []
      end

      def teardown
        @sockets.each { |s| s.close unless s.closed? }
        super
      end

      def pair(type)
        UNIXSocket.pair(type).tap { |p| @sockets.concat(p) }
      end

      def frames
        [Frame.new(can_id: 0x305, data: "\x04\xBE".b),
         Frame.new(can_id: 0x1234 | Frame::EFF_FLAG, data: "\x08\x75".b),
         Frame.new(can_id: 0x19F21123 | Frame::EFF_FLAG, data: "\xA0".b * 12, fd_flags: 1),
         Frame.new(can_id: 0x080, data: ''.b),
         Frame.new(can_id: 0x305 | Frame::RTR_FLAG, len: 2)]
      end

      def dispatcher
        @dispatcher ||= begin
          app = load_app(EXAMPLE)
          @plan = Network::Generator.plan_profile(app, AwesomeRobot::Profiles::Live::Base.syskit_profile).plan
          Dispatcher.from_plan(@plan, 'can0')
        end
      end

      def test_reads_one_record_per_message_whatever_its_size
        writer, reader = pair(:SEQPACKET)
        frames.each { |f| writer.write(FrameStructs.encode(f)) }
        writer.close
        read = FrameReader.new(reader, clock: -> { 42 }).each.to_a
        assert_equal frames.map { |f| f.dup.tap { |x| x.time = 42 } }, read
      end

      def test_reads_fixed_size_records_from_a_stream
        writer, reader = pair(:STREAM)
        classic = frames.reject(&:fd?)
        classic.each { |f| writer.write(FrameStructs.encode(f)) }
        writer.close
        assert_equal classic.map(&:can_id), FrameReader.new(reader, mtu: 16).each.map(&:can_id)
      end

      def test_a_stream_cut_inside_a_record_is_an_error
        writer, reader = pair(:STREAM)
        writer.write("\0" * 20)
        writer.close
        frame_reader = FrameReader.new(reader, mtu: 16)
        frame_reader.read
        error = assert_raises(InterfaceError) { frame_reader.read }
        assert_match(/4 bytes/, error.message)
      end

      def test_monitors_a_bus_until_the_input_ends
        writer, reader = pair(:SEQPACKET)
        (frames * 10).each { |f| writer.write(FrameStructs.encode(f)) }
        writer.close
        report = Monitor.new(dispatcher, reader, out: StringIO.new, live: false).run
        counts = report.devices.to_h { |d| [d.name, d.frames] }
        assert_equal({ 'n2k' => 10, 'sync' => 0, 'temperature_sensor' => 10, 'water_temperature' => 20 }, counts)
        assert_equal([[0x080, 10]], report.unclaimed.map { |r| [r.key, r.frames] })
        assert_equal [50, 10, 10], [report.traffic.frames, report.traffic.fd, report.traffic.rtr]
      end

      # As replay does: the frames the plan declares on the bus against
      # those read.
      def test_compares_the_traffic_read_with_the_declared_frames
        writer, reader = pair(:SEQPACKET)
        (frames * 3).each { |f| writer.write(FrameStructs.encode(f)) }
        writer.close
        report = Monitor.new(dispatcher, reader, out: StringIO.new, live: false,
                                                 declared_bus: @plan.find_bus('can0')).run
        seen = report.declared.rows.to_h { |row| [row.frame.id, row.frames] }
        assert_equal [3, 3, 0], seen.values_at(0x1234, 0x80, 0x301)
        assert_includes report.declared.undeclared.map(&:key), 0x305
        assert_match(/declared/i, ReportText.render(report))
      end

      def test_refreshes_the_table_while_frames_come
        writer, reader = pair(:SEQPACKET)
        out = StringIO.new
        thread = Thread.new do
          # Long enough for two refreshes even on a loaded machine.
          12.times do
            frames.first(2).each { |f| writer.write(FrameStructs.encode(f)) }
            sleep 0.05
          end
          writer.close
        end
        Monitor.new(dispatcher, reader, out: out, interval: 0.05, live: true,
                                        source: { 'interface' => 'test' }).run
        thread.join
        tables = out.string.split("(Ctrl-C to stop)\n")
        assert_operator tables.size, :>=, 2, out.string
        assert_match(%r{^Device +Filter +Frames +IDs +First \(s\) +Last \(s\) +Rate \(/s\) +Now \(/s\)$}, out.string)
        assert_includes out.string, 'interface test: '
      end

      # A reader that always has a frame, as a saturated bus, until +out+
      # shows +tables+ tables (or, should the monitor never refresh, a
      # number of frames no test waits for). Not timed: a loaded machine
      # only makes it take longer.
      class BusyReader
        def initialize(frame, out, tables, limit: 20_000_000)
          @frame = frame
          @out = out
          @tables = tables
          @left = limit
        end

        def read_nonblock
          @left -= 1
          return if @left.negative? || ((@left % 1024).zero? && @out.string.scan('(Ctrl-C to stop)').size >= @tables)

          @frame
        end
      end

      def test_refreshes_the_table_of_a_bus_that_never_pauses
        out = StringIO.new
        reader = BusyReader.new(frames.first, out, 3)
        Monitor.new(dispatcher, nil, reader: reader, out: out, interval: 0.01, live: true).run
        assert_operator out.string.scan('(Ctrl-C to stop)').size, :>=, 3
      end

      def test_stops_after_the_duration
        _writer, reader = pair(:SEQPACKET)
        started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        report = Monitor.new(dispatcher, reader, out: StringIO.new, interval: 0.05, live: false).run(duration: 0.2)
        elapsed = Process.clock_gettime(Process::CLOCK_MONOTONIC) - started
        # Never before the duration; soon after it (a loaded machine, or
        # the suite's process tests running beside this one, may delay the
        # last poll by a second or more).
        assert_operator elapsed, :>=, 0.2
        assert_operator elapsed, :<, 5.0
        assert_equal 0, report.traffic.frames
      end

      def test_ctrl_c_ends_with_the_report
        writer, reader = pair(:SEQPACKET)
        frames.each { |f| writer.write(FrameStructs.encode(f)) }
        monitor = Monitor.new(dispatcher, reader, out: StringIO.new, live: false)
        main = Thread.current
        interrupter = Thread.new do
          sleep 0.1
          main.raise(Interrupt)
        end
        report = monitor.run
        interrupter.join
        assert_equal 5, report.traffic.frames
      end

      def test_monitor_of_a_missing_interface_is_a_clear_error
        out, err, status = run_cli('bus', 'monitor', 'Live::Base', '--bus', 'can0', '--interface', 'nosuchcan0',
                                   '--app', EXAMPLE)
        assert_equal 1, status
        assert_equal '', out
        assert_match(/\Ano network interface named 'nosuchcan0'\n  hint: .*sudo ip link add dev vcan0 type vcan/, err)
        assert_equal 2, err.lines.size, 'no backtrace'
      end

      def test_monitor_of_an_interface_that_is_not_can
        _, err, status = run_cli('bus', 'monitor', 'Live::Base', '--bus', 'can0', '--interface', 'lo', '--app', EXAMPLE)
        assert_equal 1, status
        assert_match(/\A'lo' is not a CAN interface/, err)
      end

      def test_without_can_support_opening_a_socket_says_what_to_load
        begin
          fd = SocketCAN.raw_socket
        rescue InterfaceError => e
          assert_match(/CAN sockets are not available on this machine/, e.message)
          assert_match(/modprobe can_raw/, e.hint)
          return
        end
        SocketCAN.c_close(fd)
        skip 'this machine has CAN sockets'
      end

      def test_monitors_a_vcan_interface
        iface = SocketCAN.can_interfaces.find { |n| n.start_with?('vcan') }
        skip "no vcan interface here (#{SocketCAN::VCAN_HINT})" unless iface

        reader = SocketCAN.open(iface).tap { |io| @sockets << io }
        writer = SocketCAN.open(iface).tap { |io| @sockets << io }
        frames.each { |f| writer.syswrite(FrameStructs.encode(f)) }
        report = Monitor.new(dispatcher, reader, out: StringIO.new, live: false).run(duration: 0.3)
        assert_equal({ 'n2k' => 1, 'sync' => 0, 'temperature_sensor' => 1, 'water_temperature' => 2 },
                     report.devices.to_h { |d| [d.name, d.frames] })
      end
    end
  end
end
