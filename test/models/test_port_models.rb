# frozen_string_literal: true

require 'helper'

module Syskit
  # The ports of task and data service models (Syskit::Models::Port), as
  # Syskit's model-level API gives them.
  class TestPortModels < Minitest::Test
    def setup
      super
      @double = Types::OpaqueType.new('/double')
      @int = Types::OpaqueType.new('/int')
      double = @double
      @source = TaskContext.new_submodel do
        input_port 'in', double
        output_port 'out', double
      end
      @sink = TaskContext.new_submodel { input_port 'in', double }
    end

    def test_a_task_models_ports_are_ports_of_that_model_by_direction
      port = @source.out_port
      assert_kind_of Models::OutputPort, port
      assert_same @source, port.component_model
      assert_equal 'out', port.name
      assert_equal port, @source.find_output_port('out')
      assert_nil @source.find_input_port('out')
      assert_kind_of Models::InputPort, @source.find_input_port('in')
      assert_equal %w[out], @source.each_output_port.map(&:name)
      assert_equal port, port.to_component_port
    end

    def test_the_orogen_model_of_a_port_is_what_its_declaration_returned
      declared = nil
      double = @double
      model = TaskContext.new_submodel { declared = output_port('p', double) }
      assert_equal declared, model.p_port.orogen_model
    end

    def test_a_service_port_has_no_component_port
      double = @double
      srv = DataService.new_submodel { output_port 'out', double }
      assert_same srv, srv.out_port.component_model
      assert_raises(ArgumentError) { srv.out_port.to_component_port }
      assert_equal srv.out_port, srv.out_port.try_to_component_port
    end

    def test_ports_can_connect_from_an_output_to_an_input_of_the_same_type
      int = @int
      other = TaskContext.new_submodel { input_port 'in', int }
      assert @source.out_port.can_connect_to?(@sink.in_port)
      refute @sink.in_port.can_connect_to?(@source.out_port)
      refute @source.out_port.can_connect_to?(other.in_port)
    end

    def test_connecting_ports_of_task_models_says_what_is_wrong
      int = @int
      other = TaskContext.new_submodel { input_port 'in', int }
      assert_raises(WrongPortConnectionDirection) { @sink.in_port.connect_to(@sink.in_port) }
      assert_raises(WrongPortConnectionDirection) { @source.out_port.connect_to(@source.out_port) }
      assert_raises(SelfConnection) { @source.out_port.connect_to(@source.in_port) }
      assert_raises(WrongPortConnectionTypes) { @source.out_port.connect_to(other.in_port) }
      error = assert_raises(DeclarationError) { @source.out_port.connect_to(@sink.in_port) }
      assert_match(/composition/, error.hint)
    end

    def test_a_port_records_the_line_that_declared_it
      double = @double
      task_line = __LINE__ + 1
      task_m = TaskContext.new_submodel { output_port 'out', double }
      srv_line = __LINE__ + 1
      srv_m = DataService.new_submodel { input_port 'in', double }
      ruby_line = __LINE__ + 1
      ruby_m = RubyTaskContext.new_submodel { output_port 'out', double }
      [[task_m.out_port, task_line], [srv_m.in_port, srv_line], [ruby_m.out_port, ruby_line]].each do |port, line|
        assert_equal Location.new(File.expand_path(__FILE__), line), port.declared_at, port.to_s
      end
    end

    def test_a_port_takes_the_orogen_modifiers_of_its_declaration
      @sink.in_port.needs_reliable_connection
      assert @sink.in_port.reliable?
    end

    def test_a_static_port_says_so
      int = @int
      task_m = TaskContext.new_submodel do
        output_port('out', int).static
        output_port 'plain', int
        dynamic_input_port(/^in_/, int).static
      end
      assert task_m.out_port.static?
      refute task_m.plain_port.static?
      assert task_m.dynamic_ports.first.instantiate('in_a').static?
    end
  end
end

module Syskit
  # The ports of task instances (Syskit::Port): connected as plan data.
  class TestTaskPorts < Minitest::Test
    def setup
      super
      double = Types::OpaqueType.new('/double')
      int = Types::OpaqueType.new('/int')
      @model = TaskContext.new_submodel do
        input_port 'in', double
        output_port 'out', double
        input_port 'count', int
      end
      @source = @model.new
      @sink = @model.new
    end

    def test_a_tasks_port_knows_its_model_and_task
      port = @source.out_port
      assert_same @source, port.component
      assert_equal @model.out_port, port.model
      assert_equal port, Port.new(@model.out_port, @source)
      assert_equal 1, { port => 1 }[Port.new(@model.out_port, @source)]
      assert_nil({ port => 1 }[@sink.out_port])
    end

    def test_connecting_task_ports_records_the_connection_on_both_tasks
      refute @source.out_port.connected_to?(@sink.in_port)
      @source.out_port.connect_to(@sink.in_port)
      assert @source.out_port.connected_to?(@sink.in_port)
      assert @sink.in_port.connected_to?(@source.out_port)
      refute @source.out_port.connected_to?(@sink.count_port)
    end

    def test_connecting_task_ports_says_what_is_wrong
      assert_raises(WrongPortConnectionDirection) { @sink.in_port.connect_to(@source.in_port) }
      assert_raises(WrongPortConnectionDirection) { @source.out_port.connect_to(@sink.out_port) }
      assert_raises(SelfConnection) { @source.out_port.connect_to(@source.in_port) }
      assert_raises(WrongPortConnectionTypes) { @source.out_port.connect_to(@sink.count_port) }
    end

    def test_a_port_of_something_that_is_not_a_task_has_no_component_port
      assert_raises(ArgumentError) { Port.new(@model.out_port, Object.new).to_component_port }
    end
  end
end
