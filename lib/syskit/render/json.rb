# frozen_string_literal: true

require 'syskit/render/output'

module Syskit
  module Render
    # The plan as a JSON document, for programs: the document
    # JSON.pretty_generate makes of Plan#to_h, special floats written as
    # strings (see #strict_generate). Same plan, same bytes.
    #
    # The json library writes the lists (tasks, devices, connections,
    # order) SLICE entries at a time and the slices go to the IO as they
    # are made (see Output), so the document is never held in memory.
    module JSON
      extend Output

      # Entries written by one call to the json library: enough for the
      # library to do the work, few enough to keep memory flat.
      SLICE = 256
      # The end of a list at the document's second level, as the json
      # library writes it ("[\n" + entries joined by ",\n" + "\n  ]").
      CLOSE = "\n  ]"
      COMMA = ','.ord
      # JSON.pretty_generate's layout. NaN and the infinities are not
      # allowed: see #strict_generate.
      PRETTY = { indent: '  ', space: ' ', object_nl: "\n", array_nl: "\n" }.freeze

      module_function

      # Writes the document to +io+; returns +io+.
      def write(plan, io)
        # json is required here, not at start-up: it adds Kernel#j and #jj,
        # which user files could then call by mistake.
        require 'json'
        state = ::JSON::State.new(PRETTY)
        state.depth = 1
        out = +"{\n  \"profile\": " << state.generate(plan.profile) << ",\n  \"robot\": " << state.generate(plan.robot)
        shared = {}.compare_by_identity # see Plan#plain_entries
        Network::Plan::LISTS.each do |list|
          out << ",\n  " << state.generate(list) << ': '
          entries(plan.public_send(list), state, out, io) { |slice| plan.plain_entries(list, slice, shared) }
        end
        io.write(out << "\n}\n")
        io
      end

      # +data+ (plain data) as an indented JSON document, ending with a
      # newline: what every JSON output of the gem (check, bus replay and
      # timing, plan diff) writes.
      def pretty(data)
        require 'json'
        "#{strict_generate(::JSON::State.new(PRETTY), data)}\n"
      end

      # +data+ as JSON through +state+, strict JSON (RFC 8259) even when it
      # holds NaN or an infinity: those are written as typelib's
      # to_simple_value writes them for JSON, the strings "NaN",
      # "Infinity" and "-Infinity". The json library refuses them first,
      # so data without them (nearly always) is never walked.
      def strict_generate(state, data)
        state.generate(data)
      rescue ::JSON::GeneratorError
        state.generate(strict(data))
      end

      # +value+ with its special floats replaced by their strings.
      def strict(value)
        case value
        when Float then value.finite? ? value : special_float(value)
        when Hash then value.transform_values { |v| strict(v) }
        when Array then value.map { |v| strict(v) }
        else value
        end
      end

      # "NaN", "Infinity" or "-Infinity".
      def special_float(value)
        return 'NaN' if value.nan?

        value.positive? ? 'Infinity' : '-Infinity'
      end

      # Writes a list whose entries the block makes plain, a slice at a time.
      def entries(entries, state, out, io)
        return out << state.generate([]) if entries.empty?

        entries.each_slice(SLICE).with_index do |slice, i|
          Output.flush(continue_list(strict_generate(state, yield(slice)), i.zero?, out), io)
        end
        out << CLOSE
      end

      # The json library writes a slice as a list of its own. Its end is
      # dropped (the next slice, or the end of the list, follows), and the
      # "[" of every slice but the first becomes the "," after the previous
      # one. Both are done in place: a substring would share the slice's
      # memory, which would then wait for the garbage collector instead of
      # being freed by #clear.
      def continue_list(slice, first, out)
        slice.setbyte(0, COMMA) unless first
        slice.delete_suffix!(CLOSE)
        out << slice
        slice.clear
        out
      end
    end
  end
end
