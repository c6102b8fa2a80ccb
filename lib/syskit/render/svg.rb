# frozen_string_literal: true

require 'open3'
require 'syskit/render/dot'

module Syskit
  module Render
    # The DOT graph drawn by Graphviz's dot as SVG. Graphviz is not a
    # dependency of the gem: without it, a clear error says what to install.
    module Svg
      extend Output

      module_function

      # Writes the SVG of +plan+ to +io+ (+links+: see Dot); returns +io+.
      def write(plan, io, dot: dot_command, links: nil, all_ports: false)
        io.write(draw(Dot.write(plan, StringIO.new(+''), links: links, all_ports: all_ports).string, dot: dot))
        io
      end

      # The SVG Graphviz draws of the DOT graph +graph+.
      def draw(graph, dot: dot_command, what: 'the plan')
        svg, err, status = Open3.capture3(dot, '-Tsvg', stdin_data: graph, binmode: true)
        return svg if status.success?

        said = err.lines.first.to_s.strip
        raise Error.new("graphviz's dot could not draw #{what} (#{ended(status)})" \
                        "#{": #{said}" unless said.empty?}",
                        hint: 'write the graph with --format dot and run dot -Tsvg on it to see what graphviz says')
      end

      # How dot ended: its exit status, or the signal that killed it (out
      # of memory, a time limit, kill).
      def ended(status)
        return "exit status #{status.exitstatus}" unless status.signaled?

        "killed by signal SIG#{Signal.signame(status.termsig)}"
      end

      # The dot executable on PATH, or an error saying how to get one.
      def dot_command
        found = ENV.fetch('PATH', '').split(File::PATH_SEPARATOR).map { |dir| File.join(dir, 'dot') }
                   .find { |path| File.file?(path) && File.executable?(path) }
        found || raise(Error.new('--format svg needs graphviz, whose dot command is not on PATH',
                                 hint: 'install graphviz (e.g. sudo apt install graphviz), or write the graph with ' \
                                       '--format dot and draw it elsewhere'))
      end
    end
  end
end
