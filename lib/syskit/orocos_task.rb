# frozen_string_literal: true

module Syskit
  # The component a task stands for: +orocos_task+ in configure methods,
  # and +self+ in +stub do ... end+ blocks. It has the task's properties as
  # methods (+orocos_task.device = 'can0'+ is +properties.device = 'can0'+),
  # its operations, and +create_input_port+ / +create_output_port+.
  #
  # No component runs here. Calling an operation records the call, and the
  # plan lists it; what the call does is what a stub block says, in either
  # of the forms real files use:
  #
  #   stub do                           # Rock's form: the operation's stub
  #     def watch(name, id, mask)
  #       create_output_port name, '/canbus/Message'
  #     end
  #   end
  #
  #   stub do                           # the seed's form: code run after configure
  #     devices.each { |dev| create_output_port dev.name, Types.canbus.Message }
  #   end
  #
  # Stub blocks run after +configure+; then each recorded call of an
  # operation a stub block defined runs that definition, in call order
  # (see Network::Configure). An operation therefore returns nil in
  # +configure+.
  class OrocosTask
    # One call of an operation: its name and arguments.
    OperationCall = Struct.new(:name, :arguments)
    NO_CALLS = [].freeze

    # The component class of +task_model+: a reader and a writer per
    # property, a method per operation. Names already taken by this class
    # (properties, create_input_port, ...) keep their meaning.
    def self.for(task_model)
      klass = Class.new(self)
      task_model.property_declarations.each_key do |name|
        next if method_defined?(name) || private_method_defined?(name)

        klass.define_method(name) { @task.property(name).read }
        klass.define_method("#{name}=") { |value| @task.property(name).write(value) }
      end
      task_model.operations.each_key do |name|
        next if klass.method_defined?(name) || private_method_defined?(name)

        klass.define_method(name) { |*args| call_operation(name, args) }
      end
      klass
    end

    attr_reader :task

    def initialize(task)
      @task = task
      @operation_calls = NO_CALLS
    end

    def properties
      @task.properties
    end

    # The operations called so far, in call order.
    def operation_calls
      @operation_calls.empty? ? NO_CALLS : @operation_calls.dup.freeze
    end

    # As TaskContext#abort, for stub blocks.
    def abort(message = nil)
      raise SystemExit.new(false, message || 'exit')
    end

    def create_input_port(name, type)
      create_port(:input, name, type)
    end

    def create_output_port(name, type)
      create_port(:output, name, type)
    end

    # Runs, in call order, the recorded calls of the operations that stub
    # blocks defined (as methods of this object).
    def run_stubbed_operations
      @operation_calls.each do |call|
        next unless singleton_class.method_defined?(call.name, false) ||
                    singleton_class.private_method_defined?(call.name, false)

        __send__(call.name, *call.arguments)
      end
    end

    def explain_missing(name)
      operations = @task.model.operations.keys.sort
      known = (operations + @task.model.property_declarations.keys).sort
      ["#{@task.model.name} has no property or operation '#{name.to_s.delete_suffix('=')}'" \
       "#{Naming.did_you_mean(name.to_s.delete_suffix('='), known)}",
       "its operations are #{operations.empty? ? '(none)' : operations.join(', ')}; " \
       'its properties are listed by properties.names']
    end

    def to_s
      "the component of #{@task}"
    end
    alias inspect to_s

    private

    def call_operation(name, args)
      @operation_calls = [] if @operation_calls.frozen?
      @operation_calls << OperationCall.new(name, args.freeze)
      nil
    end

    # The caller's location is only looked up when there is an error.
    def create_port(direction, name, type)
      @task.create_port(direction, name, type)
    rescue Syskit::Error => e
      raise e.location ? e : e.at(Location.of_caller)
    end
  end
end
