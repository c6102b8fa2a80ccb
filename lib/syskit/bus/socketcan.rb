# frozen_string_literal: true

require 'ffi'
require 'syskit/bus/errors'

module Syskit
  module Bus
    # Opens a raw CAN socket on a Linux SocketCAN interface (can0, vcan0...)
    # through libc, with CAN FD frames enabled, and returns it as a Ruby IO:
    # reads then wait in Ruby, so Ctrl-C interrupts them.
    module SocketCAN
      extend FFI::Library

      ffi_lib FFI::Library::LIBC

      PF_CAN = 29
      SOCK_RAW = 3
      CAN_RAW = 1
      SOL_CAN_RAW = 101
      CAN_RAW_FD_FRAMES = 5
      # /sys/class/net/IFACE/type of a CAN interface (ARPHRD_CAN).
      ARPHRD_CAN = 280
      SYS_NET = '/sys/class/net'
      VCAN_HINT = 'to make a virtual bus: sudo modprobe vcan; sudo ip link add dev vcan0 type vcan; ' \
                  'sudo ip link set up vcan0'

      # struct sockaddr_can's address union: ISO-TP ids or J1939 name.
      class CanAddr < FFI::Union
        layout :tp, Class.new(FFI::Struct) { layout :rx_id, :uint32, :tx_id, :uint32 },
               :j1939, Class.new(FFI::Struct) { layout :name, :uint64, :pgn, :uint32, :addr, :uint8 }
      end

      # struct sockaddr_can (linux/can.h).
      class SockaddrCan < FFI::Struct
        layout :can_family, :ushort,
               :can_ifindex, :int,
               :can_addr, CanAddr
      end

      attach_function :if_nametoindex, [:string], :uint
      attach_function :c_socket, :socket, %i[int int int], :int
      attach_function :c_bind, :bind, %i[int pointer uint], :int
      attach_function :c_setsockopt, :setsockopt, %i[int int int pointer uint], :int
      attach_function :c_close, :close, [:int], :int

      module_function

      # A raw CAN socket bound to interface +name+, as an IO. Raises an
      # InterfaceError saying what to do when it cannot be opened.
      def open(name)
        check_platform
        index = interface_index(name)
        fd = raw_socket
        begin
          enable_fd_frames(fd)
          bind(fd, index, name)
          IO.for_fd(fd, 'rb', autoclose: true)
        rescue StandardError
          c_close(fd)
          raise
        end
      end

      # The CAN interfaces of this machine, by name.
      def can_interfaces
        Dir.children(SYS_NET).select { |n| interface_type(n) == ARPHRD_CAN }.sort
      rescue SystemCallError
        []
      end

      # The ARPHRD type of interface +name+, nil when unknown.
      def interface_type(name)
        Integer(File.read(File.join(SYS_NET, name, 'type')).strip, exception: false)
      rescue SystemCallError
        nil
      end

      def check_platform
        return if FFI::Platform::OS == 'linux'

        raise InterfaceError.new("SocketCAN is Linux only; this is #{FFI::Platform::OS}",
                                 hint: 'record a log with candump -l on the robot and use syskit bus replay')
      end

      def interface_index(name)
        index = if_nametoindex(name)
        raise InterfaceError.new("no network interface named '#{name}'", hint: interfaces_hint) if index.zero?

        type = interface_type(name)
        if type && type != ARPHRD_CAN
          raise InterfaceError.new("'#{name}' is not a CAN interface (its link type is #{type}, CAN is #{ARPHRD_CAN})",
                                   hint: interfaces_hint)
        end
        index
      end

      def raw_socket
        fd = c_socket(PF_CAN, SOCK_RAW, CAN_RAW)
        return fd unless fd.negative?

        error = SystemCallError.new(nil, FFI.errno)
        case error
        when Errno::EAFNOSUPPORT, Errno::EPROTONOSUPPORT
          raise InterfaceError.new("CAN sockets are not available on this machine (#{error.message})",
                                   hint: "load the kernel's CAN support: sudo modprobe can_raw; #{VCAN_HINT}")
        when Errno::EACCES, Errno::EPERM
          raise InterfaceError.new("not allowed to open a CAN socket (#{error.message})",
                                   hint: 'raw CAN sockets may need CAP_NET_RAW in containers')
        else raise InterfaceError.new("cannot open a CAN socket: #{error.message}", hint: VCAN_HINT)
        end
      end

      # Without this option the socket only carries classic frames; old
      # kernels do not know it, and then classic frames are all there is.
      def enable_fd_frames(socket)
        on = FFI::MemoryPointer.new(:int)
        on.write_int(1)
        c_setsockopt(socket, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, on, on.size)
      end

      def bind(socket, index, name)
        addr = SockaddrCan.new
        addr[:can_family] = PF_CAN
        addr[:can_ifindex] = index
        return unless c_bind(socket, addr.to_ptr, SockaddrCan.size).negative?

        error = SystemCallError.new(nil, FFI.errno)
        hint = error.is_a?(Errno::ENETDOWN) ? "bring it up: sudo ip link set up #{name}" : interfaces_hint
        raise InterfaceError.new("cannot bind a CAN socket to '#{name}': #{error.message}", hint: hint)
      end

      def interfaces_hint
        found = can_interfaces
        return "CAN interfaces here: #{found.join(', ')}" if found.any?

        "this machine has no CAN interface; #{VCAN_HINT}"
      end
    end
  end
end
