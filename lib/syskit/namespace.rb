# frozen_string_literal: true

module Syskit
  # The objects behind the +Types+ and +OroGen+ constants: +Types.canbus.Message+
  # walks one namespace per segment of +/canbus/Message+, +OroGen.canbus.Task+
  # one per segment of +canbus::Task+. Each segment is a singleton method
  # defined when something is registered, so +Types.canbus.names+ lists them.
  class Namespace
    attr_reader :root, :path

    def initialize(root, path = [])
      @root = root
      @path = path.freeze
      @entries = {}
    end

    # Makes +value+ reachable at +segments+ (e.g. ['canbus', 'Message']).
    def add(segments, value)
      head, *rest = segments
      return define_entry(head, value) if rest.empty?

      child = @entries[head]
      child = define_entry(head, self.class.new(root, path + [head])) unless child.is_a?(Namespace)
      child.add(rest, value)
    end

    # Names reachable from here, sorted.
    def names
      @entries.keys.sort
    end

    def entry(name)
      @entries[name.to_s]
    end

    def to_s
      ([root] + path).join('.')
    end

    # Why +name+ is not here, for errors about a misspelled +Types.x.Y+.
    def explain_missing(name)
      ["#{self} has no '#{name}'#{Naming.did_you_mean(name, names)}",
       names.empty? ? "nothing is registered under #{self}" : "known under #{self}: #{names.join(', ')}"]
    end
    alias inspect to_s

    private

    def define_entry(name, value)
      @entries[name] = value
      define_singleton_method(name) { value } if name.match?(/\A[A-Za-z_]\w*\z/)
      value
    end
  end
end
