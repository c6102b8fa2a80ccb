# frozen_string_literal: true

require 'stringio'
require 'syskit/render/svg'
require 'syskit/render/composition_dot'

module Syskit
  module Doc
    # What the page of a composition model shows: its arguments, children
    # (by role, with what they require), exported ports, provided
    # services, connections, named configurations and specializations, and
    # its dataflow and hierarchy drawn by Graphviz.
    class CompositionView
      # A connection between two children's ports, as the page lists it.
      Connection = Struct.new(:from, :to, :policy)

      attr_reader :model, :catalog

      def initialize(catalog, model, dot: nil, **_site)
        @catalog = catalog
        @model = model
        @dot = dot
      end

      def arguments
        model.argument_defaults
      end

      def children
        model.each_child.map { |_, child| child }
      end

      def exports
        model.exports.values
      end

      def services
        model.each_data_service.to_a
      end

      def connections
        model.port_connections.map do |c|
          policy = Render::Output.policy(c.policy.empty? ? Network::Policy::DATA : Network::Policy.of(c.policy), +'')
          Connection.new("#{c.from.child_name}.#{c.from.name}", "#{c.to.child_name}.#{c.to.name}", policy)
        end
      end

      def configurations
        model.configurations
      end

      def specializations
        model.specializations
      end

      # Definitions of the app's profiles whose model is this one.
      def definitions
        catalog.entries(:profile).flat_map do |entry|
          entry.object.definitions.values.select { |d| d.component_model.equal?(model) }
               .map { |d| [entry, d] }
        end
      end

      def dot?
        !@dot.nil?
      end

      # The dataflow graph as SVG (the block gives a model page's URL).
      def dataflow_svg(&)
        svg(Render::CompositionDot.dataflow(model, links: links(&)), 'dataflow')
      end

      def hierarchy_svg(&)
        svg(Render::CompositionDot.hierarchy(model, links: links(&)), 'hierarchy')
      end

      private

      def links
        kinds = %i[device service task_model composition]
        kinds.flat_map { |k| catalog.entries(k) }.to_h { |e| [e.name, yield(e)] }
      end

      # Graphviz's SVG without its prolog, its ids prefixed (a page holds
      # two graphs, whose ids would collide).
      def svg(graph, prefix)
        return unless @dot

        Render::Svg.draw(graph, dot: @dot, what: "the graph of #{model.short_name}")
                   .sub(/\A.*?(?=<svg\b)/m, '').gsub(/\bid="([^"]*)"/) { %(id="#{prefix}-#{Regexp.last_match(1)}") }
      end
    end
  end
end
