# frozen_string_literal: true

module Syskit
  # Errors in models and their use, under the names Syskit gives them
  # (+assert_raises(Syskit::InvalidSelection) { ... }+, +rescue
  # Syskit::Ambiguous+). Like every error of the gem, each may carry the
  # user's file:line and a hint.

  # Syskit's base of what is ambiguous: several services, specializations
  # or ports fit where one is needed.
  class Ambiguous < SpecError; end

  # Ports of a service mapped onto ports of a component that cannot
  # stand for them (+provides Srv, 'in' => 'nonexistent'+).
  class InvalidPortMapping < SpecError; end

  # A selection (+use('child' => Model)+) that cannot fulfil what it is
  # selected for.
  class InvalidSelection < SpecError; end

  # No service of a component fits the service model asked for.
  class NoMatchingService < Ambiguous; end

  # A service name that a component model does not have.
  class UnknownServiceName < SpecError; end

  # Requirements that cannot be turned into tasks.
  class InstanciationError < SpecError; end

  # A name (+child_name+, a definition) that nothing in the context resolves.
  class NameResolutionError < InstanciationError; end

  # Several specializations of a composition fit one selection.
  class AmbiguousSpecialization < Ambiguous; end

  # Several ports of a component fit a service port.
  class AmbiguousPortMappings < Ambiguous; end

  # A port of a composition whose children have several candidates.
  class AmbiguousPortOnCompositeModel < Ambiguous; end

  # +connect_to+ between components whose ports match in more than one way.
  class AmbiguousAutoConnection < Ambiguous; end

  # +connect_to+ between components none of whose ports match: it says
  # which outputs and inputs there were (+PP.pp(error)+ lists them).
  class InvalidAutoConnection < Error
    attr_reader :source, :sink

    def initialize(source, sink, location: nil)
      @source = source
      @sink = sink
      super("no connection from #{source} to #{sink}: no output of the first has the type of an input " \
            'of the second',
            location: location, hint: 'connect the ports by name: source.out_port.connect_to sink.in_port')
    end

    def pretty_print(printer)
      printer.text(message)
      list_ports(printer, "the outputs of #{source} are", source, :each_output_port)
      list_ports(printer, "the inputs of #{sink} are", sink, :each_input_port)
    end

    private

    def list_ports(printer, title, component, enumerator)
      return unless component.respond_to?(enumerator)

      printer.nest(2) do
        printer.breakable
        printer.text(title)
        printer.nest(2) do
          printer.breakable
          printer.seplist(component.public_send(enumerator)) { |port| printer.text("#{port.name}[#{port.type.name}]") }
        end
      end
    end
  end

  # Models that cannot be merged into one (two task models, unrelated).
  class IncompatibleComponentModels < Error; end

  # A connection from an input, or to an output.
  class WrongPortConnectionDirection < Error; end

  # A connection between ports of different types.
  class WrongPortConnectionTypes < Error; end

  # A connection from a component to itself.
  class SelfConnection < Error; end

  # Specializations of a composition that contradict one another.
  class NonSymmetricSpecializationConstraint < Error; end

  # A dynamic service block that does not provide its service.
  class InvalidDynamicServiceBlock < Error; end

  # A task that needs a name and has none.
  class TaskNameRequired < DeclarationError; end

  # Something the gem expected never to happen.
  class InternalError < Error; end

  module Models
    # A port asked of a composition child that its models do not have.
    class InvalidCompositionChildPort < Error
      attr_reader :composition_model, :child_name, :port_name

      def initialize(composition_model, child_name, port_name, location: nil)
        @composition_model = composition_model
        @child_name = child_name
        @port_name = port_name
        child = composition_model.find_child(child_name)
        known = child ? child.ports.keys.sort : []
        super("#{child || "#{composition_model}.#{child_name}_child"} has no port '#{port_name}'",
              location: location, hint: known.empty? ? nil : "its ports are #{known.join(', ')}")
      end
    end
  end

  # A component model that cannot provide the service it declares (no
  # port, or several, for a port of the service; a mapping naming a port
  # that does not exist): a declaration error, so an ArgumentError too.
  class InvalidProvides < DeclarationError; end
end
