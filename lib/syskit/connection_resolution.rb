# frozen_string_literal: true

# Connection resolution between components (Syskit.resolve_connections).
module Syskit
  # Which output connects to which input when two components are connected
  # without naming ports (+a_child.connect_to b_child+): each output goes to
  # the input of its type, the one of its name when several have its type.
  # Returns [output, input] pairs; raises AmbiguousAutoConnection when an
  # output has several such inputs, or when several outputs feed an input
  # that does not multiplex.
  def self.resolve_connections(outputs, inputs, location: nil)
    pairs = outputs.filter_map do |out|
      input = autoconnect_input(out, inputs, location)
      [out, input] if input
    end
    pairs.group_by(&:last).each do |input, feeding|
      next if feeding.size < 2 || input.multiplexes?

      raise AmbiguousAutoConnection.new(
        "#{feeding.map { |out, _| out.name }.join(', ')} would all connect to #{input.name}, " \
        'which does not multiplex', location: location, hint: 'connect the ports explicitly'
      )
    end
    pairs
  end

  # The input of +inputs+ that +out+ connects to (see resolve_connections);
  # nil when none has its type.
  def self.autoconnect_input(out, inputs, location)
    candidates = inputs.select { |i| i.type == out.type }
    return candidates.first if candidates.size < 2

    named = candidates.select { |i| i.name == out.name }
    return named.first if named.size == 1

    raise AmbiguousAutoConnection.new(
      "#{out.name} could connect to several inputs: #{candidates.map(&:name).sort.join(', ')}",
      location: location, hint: "connect it explicitly: #{out.name}_port.connect_to(#{candidates.first.name}_port)"
    )
  end
  private_class_method :autoconnect_input
end
