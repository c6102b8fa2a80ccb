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

      # Writes the SVG of +plan+ to +io+; returns +io+.
      def write(plan, io, dot: dot_command)
        svg, err, status = Open3.capture3(dot, '-Tsvg', stdin_data: Dot.render(plan), binmode: true)
        unless status.success?
          said = err.lines.first.to_s.strip
          raise Error.new("graphviz's dot could not draw the plan (#{ended(status)})#{": #{said}" unless said.empty?}",
                          hint: 'write the graph with --format dot and run dot -Tsvg on it to see what graphviz says')
        end

        io.write(svg)
        io
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
