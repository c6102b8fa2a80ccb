# frozen_string_literal: true

module Syskit
  module Orogen
    # Statements of a +stream_aligner do ... end+ block in a task context:
    #
    #   stream_aligner do
    #     max_latency 0.2
    #     align_port 'scans', 0.025
    #   end
    #
    # Once evaluated, the task has the properties and ports oroGen's plugin
    # gives it (see #add_interface), so that configuration files and
    # connections naming them are checked.
    class StreamAlignerDSL
      include StatementsDSL

      def initialize(task_dsl, task_spec, plugin)
        @task_dsl = task_dsl
        @task_spec = task_spec
        @plugin = plugin
      end

      def dsl_context
        "#{@task_dsl.dsl_context}'s #{plugin_name} block"
      end

      def max_latency(seconds)
        @plugin.max_latency = Float(seconds)
      rescue ArgumentError, TypeError
        raise SpecError.new("max_latency #{seconds.inspect}: the latency is a number of seconds",
                            location: Location.of_caller, hint: 'write max_latency 0.1')
      end

      # Aligns the samples of the input port +name+, expected every +period+
      # seconds (0: unknown). A priority, as the transformer takes it, does
      # not change the task's interface.
      def align_port(name, period = 0, _priority_or_time_field = nil)
        port = input_port(name, 'align_port')
        @plugin.streams << StreamAlignerSpec::Stream.new(port.name, Float(period))
      end

      # Evaluates +block+, then gives the task what the plugin adds (and
      # makes it need configuring, as the plugin does). Returns the plugin's
      # declarations.
      def evaluate(location, &block)
        instance_eval(&block) if block
        return @plugin unless @plugin.needed?

        unless @plugin.max_latency
          raise SpecError.new("#{@task_spec.name}'s #{plugin_name} block declares no max_latency",
                              location: location, hint: "add max_latency 0.1 (seconds) to the #{plugin_name} block")
        end

        add_interface
        @task_spec.needs_configuration = true
        @plugin
      end

      private

      def plugin_name
        'stream_aligner'
      end

      # What oroGen's stream aligner adds to the task: its latency and
      # status period, a period per aligned port and a status port.
      def add_interface
        @task_dsl.plugin_property('aggregator_max_latency', '/double', @plugin.max_latency)
        @task_dsl.plugin_property('stream_aligner_status_period', '/double', 1.0)
        @task_dsl.plugin_output_port('stream_aligner_status', '/aggregator/StreamAlignerStatus', typekit: 'aggregator')
        add_stream_periods
      end

      def add_stream_periods
        @plugin.streams.each { |stream| @task_dsl.plugin_property("#{stream.port}_period", '/double', stream.period) }
      end

      def input_port(name, statement)
        port = @task_spec.find_port(name)
        return port if port&.input?

        raise no_port(name, statement, :input)
      end

      # The error for a statement naming a port the task does not have (of
      # +direction+, when given).
      def no_port(name, statement, direction = nil)
        ports = @task_spec.all_ports.values
        ports = ports.select { |p| p.direction == direction } if direction
        names = ports.map(&:name).sort
        what = direction ? "#{direction} port" : 'port'
        hint = names.empty? ? "declare the #{what} before this block" : "its #{what}s are #{names.join(', ')}"
        SpecError.new("#{statement} '#{name}': #{@task_spec.name} has no #{what} '#{name}'" \
                      "#{Naming.did_you_mean(name.to_s, names)}", location: Location.of_caller, hint: hint)
      end
    end

    # Statements of a +transformer do ... end+ block (oroGen's transformer
    # plugin):
    #
    #   transformer do
    #     max_latency 0.1
    #     transform 'imu', 'body'                     # needed: imu_frame, body_frame properties
    #     align_port 'imu_samples', 0.01
    #     transform_output 'pose_samples', 'body' => 'world'
    #     associate_frame_to_ports 'laser', 'scans'
    #   end
    class TransformerDSL < StreamAlignerDSL
      # A transformation the task needs; its frames are named by properties.
      def transform(from, to)
        @plugin.add_frames([from.to_s, to.to_s], configurable: true)
        @plugin.transforms << TransformerSpec::Transform.new(from.to_s, to.to_s)
      end
      alias transformation transform

      def transform_input(port_name, transform)
        transform_port(port_name, transform, :input, 'transform_input')
      end

      def transform_output(port_name, transform)
        transform_port(port_name, transform, :output, 'transform_output')
      end

      def frames(*names)
        @plugin.add_frames(names.flatten.map(&:to_s))
      end

      def configurable_frames(*names)
        @plugin.add_frames(names.flatten.map(&:to_s), configurable: true)
      end

      # The data of +port_names+ is expressed in +frame+.
      def associate_frame_to_ports(frame, *port_names)
        frames(frame)
        port_names.flatten.each do |name|
          port = @task_spec.find_port(name) || raise(no_port(name, 'associate_frame_to_ports'))
          @plugin.port_frames[port.name] = frame.to_s
        end
      end

      # The order in which the transformer applies transformations: no
      # bearing on the interface.
      def transform_priority(_priority); end

      private

      def plugin_name
        'transformer'
      end

      def transform_port(port_name, transform, direction, statement)
        from, to = one_transform(transform, port_name, statement)
        port = @task_spec.find_port(port_name)
        raise no_port(port_name, statement, direction) unless port && port.direction == direction

        @plugin.add_frames([from, to])
        @plugin.port_transforms[port.name] = TransformerSpec::Transform.new(from, to)
      end

      def one_transform(transform, port_name, statement)
        return transform.first.map(&:to_s) if transform.is_a?(Hash) && transform.size == 1

        raise SpecError.new("#{statement} '#{port_name}': the transformation is one 'from' => 'to' pair, " \
                            "got #{transform.inspect}",
                            location: Location.of_caller,
                            hint: "write #{statement} '#{port_name}', 'body' => 'world'")
      end

      # What oroGen's transformer adds to the task: its latency and status,
      # the static and dynamic transformations it reads, a period per
      # aligned port and a property per frame whose name is configured.
      def add_interface
        @task_dsl.plugin_property('transformer_max_latency', '/double', @plugin.max_latency)
        @task_dsl.plugin_output_port('transformer_stream_aligner_status', '/aggregator/StreamAlignerStatus',
                                     typekit: 'aggregator')
        @task_dsl.plugin_output_port('transformer_status', '/transformer/TransformerStatus', typekit: 'transformer')
        @task_dsl.plugin_property('transformer_status_period', '/double', 1.0)
        @task_dsl.plugin_property('static_transformations', '/std/vector</base/samples/RigidBodyState>', nil)
        @task_dsl.plugin_input_port('dynamic_transformations', '/base/samples/RigidBodyState')&.multiplexes
                 &.needs_reliable_connection
        add_stream_periods
        @plugin.configurable_frames.each { |frame| @task_dsl.plugin_property("#{frame}_frame", '/std/string', frame) }
      end
    end
  end
end
