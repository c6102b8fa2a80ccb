# frozen_string_literal: true

module Syskit
  # What +connect_to+ checks, on the ports of models and of tasks alike:
  # an output to an input of the same type, of two different components.
  # The errors are Syskit's (WrongPortConnectionDirection, SelfConnection,
  # WrongPortConnectionTypes), located at the user's +connect_to+.
  module PortConnectionCheck
    # +same_owner+: whether both ports belong to one component (+owner+
    # says what that is: 'component model', 'task').
    def self.check!(source, sink, location, same_owner:, owner:)
      error = if !source.output? then [WrongPortConnectionDirection, "#{source} is not an output port"]
              elsif !sink.respond_to?(:input?) || !sink.input?
                [WrongPortConnectionDirection, "#{sink} is not an input port"]
              elsif same_owner then [SelfConnection, "they are ports of the same #{owner}"]
              elsif source.type != sink.type
                [WrongPortConnectionTypes, "their types differ (#{type_of(source)} and #{type_of(sink)})"]
              end
      return unless error

      raise error[0].new("cannot connect #{source} to #{sink}: #{error[1]}",
                         location: location, hint: 'connect an output port to an input port of the same type')
    end

    # The type as declared, with the type it resolves to when it is a
    # typedef (/base/commands/Joints (= /base/samples/Joints)).
    def self.type_of(port)
      port.respond_to?(:type_description) ? port.type_description : port.type.name
    end
  end
end
