# frozen_string_literal: true

module Syskit
  # A call of the user's that Ruby refused before one of the gem's methods
  # ran: the wrong number of arguments, an unknown or a missing keyword
  # (+device(Devices::IMU, 'imu')+ for +device(Devices::IMU, as: 'imu')+).
  # Ruby's message does not say which method: it is found from the frame
  # Ruby makes for it, when the error is reported, so that the message
  # names the statement and the hint says what it takes.
  class RefusedCall
    RUBY_MESSAGE = /\A(wrong number of arguments|unknown keywords?:|missing keywords?:)/
    METHOD_NAME = /\A[a-z_]\w*[?!=]?\z/i

    # The refused call +exception+ reports; nil for any other error.
    def self.of(exception)
      return unless exception.instance_of?(ArgumentError) && exception.message.match?(RUBY_MESSAGE)

      callee, caller = exception.backtrace_locations&.first(2)
      return unless callee && caller && gem_frame?(callee) && !gem_frame?(caller)

      method = find_method(callee, caller)
      new(method, exception.message) if method
    end

    def self.gem_frame?(frame)
      (frame.absolute_path || frame.path).start_with?(Location::GEM_LIB)
    end

    # The method whose definition +frame+ is. A method defined with +def+
    # is named by the frame; one made from a block (+define_method+, as
    # dsl_attribute makes them) is among those defined at that line, the
    # one the user's line (+caller+) calls.
    def self.find_method(frame, caller)
      where = [frame.absolute_path || frame.path, frame.lineno]
      name = frame.label
      return method_named(name, where) if name.match?(METHOD_NAME)

      candidates = methods_defined_at(where).uniq(&:name)
      return candidates.first if candidates.size <= 1

      line = Location.from(caller)&.source_line.to_s
      called = candidates.select { |m| line.include?("#{m.name}(") }
      called.first if called.size == 1
    end

    def self.method_named(name, where)
      ObjectSpace.each_object(Module) do |mod|
        next unless mod.method_defined?(name, false) || mod.private_method_defined?(name, false)

        method = mod.instance_method(name)
        return method if method.source_location == where
      end
      nil
    end

    def self.methods_defined_at(where)
      found = []
      ObjectSpace.each_object(Module) do |mod|
        (mod.instance_methods(false) + mod.private_instance_methods(false)).each do |name|
          method = mod.instance_method(name)
          found << method if method.source_location == where
        end
      end
      found
    end

    attr_reader :callee

    def initialize(callee, ruby_message)
      @callee = callee
      @ruby_message = ruby_message
    end

    # [message, hint] as UserCode.describe gives them.
    def describe
      ["#{callee.name}: #{@ruby_message}", "#{callee.name} takes (#{parameters})"]
    end

    # The method's parameters as they are written in a call; a module may
    # say what a method it made takes (+parameters_of(name)+: a device
    # attribute takes what its filter takes).
    def parameters
      owner = callee.owner
      parameters = owner.respond_to?(:parameters_of) && owner.parameters_of(callee.name)
      Arguments.as_written(parameters || callee.parameters).join(', ')
    end
  end
end
