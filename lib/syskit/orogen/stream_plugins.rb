# frozen_string_literal: true

module Syskit
  module Orogen
    # What a task context's +stream_aligner do ... end+ block declares: the
    # input ports whose samples are aligned in time, with the period
    # expected of each, and the latency the aligner waits for at most.
    class StreamAlignerSpec
      Stream = Struct.new(:port, :period)

      attr_accessor :max_latency
      attr_reader :streams

      def initialize
        @streams = []
      end

      # Whether the block aligns some port (then it adds its interface).
      def needed?
        !streams.empty?
      end
    end

    # What a task context's +transformer do ... end+ block declares (oroGen's
    # transformer plugin): the frames the task works in, the
    # transformations it needs, the ports that carry transformations or data
    # expressed in a frame, and the ports it aligns as a stream aligner does.
    #
    # A task model answers +transformer+ with it, and
    # +find_transform_of_port+ / +find_frame_of_port+ with what it says of a
    # port, inherited from the parent task context.
    class TransformerSpec < StreamAlignerSpec
      Transform = Struct.new(:from, :to)

      # Frame names, in the order declared; those whose name the task takes
      # as a property (<frame>_frame).
      attr_reader :frames, :configurable_frames
      # The transformations the task needs.
      attr_reader :transforms
      # Port name => Transform it reads or writes; port name => frame of its data.
      attr_reader :port_transforms, :port_frames
      # The transformer of the parent task context, if it has one.
      attr_accessor :parent

      def initialize(parent = nil)
        super()
        @parent = parent
        @max_latency = parent&.max_latency
        @frames = []
        @configurable_frames = []
        @transforms = []
        @port_transforms = {}
        @port_frames = {}
      end

      # Whether the task runs a transformer: it needs transformations or
      # aligns ports (then the block adds the transformer's interface).
      def needed?
        !transforms.empty? || super || parent&.needed? || false
      end

      def add_frames(names, configurable: false)
        names.each do |name|
          frames << name unless frames.include?(name)
          configurable_frames << name if configurable && !configurable_frames.include?(name)
        end
      end

      def each_frame(&)
        all = parent ? (parent.each_frame.to_a | frames) : frames
        all.each(&)
      end

      # The transformation port +port+ (a port or its name) reads or writes.
      def find_transform_of_port(port)
        name = port.respond_to?(:name) ? port.name : port.to_s
        port_transforms[name] || parent&.find_transform_of_port(name)
      end

      # The frame the data of +port+ (a port or its name) is expressed in.
      def find_frame_of_port(port)
        name = port.respond_to?(:name) ? port.name : port.to_s
        port_frames[name] || parent&.find_frame_of_port(name)
      end
    end
  end
end
