# frozen_string_literal: true

require 'stringio'

module Syskit
  module Render
    # How renderers write: into a String, handed to the IO a chunk at a
    # time. The plan of 10,000 devices is 16 MB of JSON; building it as one
    # string makes Ruby's garbage collector run over the whole heap each
    # time the string outgrows the collector's malloc limit, a cost that
    # grows with both the output and the heap.
    #
    # A renderer defines +write(plan, io)+ and gets +render(plan)+ (the same
    # bytes as a String) by extending this module.
    module Output
      CHUNK = 1 << 16

      # Writes +out+ to +io+ and empties it once it holds a chunk; returns
      # +out+.
      def self.flush(out, io)
        return out if out.bytesize < CHUNK

        io.write(out)
        out.clear
      end

      # A connection's policy as people read it: "buffer 20" or "data".
      # 'front (front.local)': a process server of the plan ({'name',
      # 'host'}), its host when it is not its name.
      def self.process_server(server)
        server['host'] == server['name'] ? server['name'] : "#{server['name']} (#{server['host']})"
      end

      def self.policy(policy, out)
        out << policy['type']
        policy['type'] == 'buffer' ? out << ' ' << policy['size'].to_s : out
      end

      # Names of values that are CAN identifiers or masks (can_id, filterMask,
      # id, masks, filters...): written in hex, as people write them.
      ID_NAME = /(?:\A|_)(?:id|mask|filter)s?\z|(?<=[a-z0-9])(?:Id|Mask|Filter)s?\z/

      # Property names repeat across a plan's tasks: each is matched once.
      ID_NAMES = Hash.new { |cache, name| cache[name] = ID_NAME.match?(name.to_s) }
      private_constant :ID_NAMES

      def self.id_name?(name)
        ID_NAMES[name]
      end

      # 0x1F21100: an id or mask as the robot's declarations write it.
      def self.hex(value)
        value.negative? ? value.to_s : "0x#{value.to_s(16).upcase}"
      end

      # The plan as a String.
      def render(plan)
        io = StringIO.new(+'')
        write(plan, io)
        io.string
      end
    end
  end
end
