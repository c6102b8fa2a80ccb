# frozen_string_literal: true

module Syskit
  # The modules behind the +Types+ and +OroGen+ constants. Each entry is
  # reachable in both forms Rock code writes: a method named as the entry
  # (+OroGen.gps_ublox.Task+, +Types.canbus.Message+) and a constant
  # (+OroGen::GpsUblox::Task+, +Types::Canbus::Message+). Both are defined
  # when something is registered, so they are the same object, and
  # +class OroGen::GpsUblox::Task ... end+ reopens the task model.
  class Namespace < Module
    # An argument not given to an entry's method (see #define_entry).
    NONE = Object.new.freeze
    private_constant :NONE

    # Segments of the path from the root ('canbus', 'Message').
    attr_reader :segments

    def initialize(root, segments = [])
      super()
      @root_name = root
      @segments = segments.freeze
      @entries = {}
    end

    # Makes +value+ reachable at +path+ (e.g. ['canbus', 'Message']).
    def add(path, value)
      head, *rest = path
      return define_entry(head, value) if rest.empty?

      child = @entries[head]
      child = define_entry(head, self.class.new(@root_name, segments + [head])) unless child.is_a?(Namespace)
      child.add(rest, value)
    end

    # Makes the entry at +path+ unreachable (and the namespaces that lead
    # to it once they are empty).
    def remove(path)
      head, *rest = path
      entry = @entries[head]
      if rest.empty? || (entry.is_a?(Namespace) && entry.remove(rest).names.empty?)
        @entries.delete(head)
        singleton_class.send(:remove_method, head) if singleton_class.method_defined?(head, false)
        constant = Namespace.constant_for(head)
        remove_const(constant) if constant && const_defined?(constant, false)
      end
      self
    end

    # Names reachable from here, sorted.
    def names
      @entries.keys.sort
    end

    # The entry called +name+ (its method name, 'gps_ublox'), nil if none.
    def entry(name)
      @entries[name.to_s]
    end

    def to_s
      ([@root_name] + segments).join('.')
    end
    alias inspect to_s

    # Why +name+ (a method or constant name) is not here, for errors about
    # a misspelled +Types.x.Y+ or +OroGen::X::Y+.
    def explain_missing(name)
      ["#{self} has no '#{name}'#{Naming.did_you_mean(name, names)}",
       names.empty? ? "nothing is registered under #{self}" : "known under #{self}: #{names.join(', ')}"]
    end

    # Forgets the entries, here and below: after an app is unloaded, Ruby's
    # method caches (in code that called +OroGen.x+) may keep this module
    # for a while, and it must not keep the app's models then.
    def forget
      @entries.each_value { |value| value.forget if value.is_a?(Namespace) }
      @entries.clear
      constants(false).each { |constant| remove_const(constant) }
    end

    # The constant an entry called +name+ is reachable as ('gps_ublox' is
    # GpsUblox), nil when it cannot be one.
    def self.constant_for(name)
      constant = Naming.camelize(name)
      constant if Naming.constant_name?(constant)
    end

    private

    def define_entry(name, value)
      @entries[name] = value
      # An entry never hides a public method every module has (name, hash,
      # ...): it stays reachable as a constant and through #entry.
      # The method reads the entry rather than keeping it (see #forget).
      if name.match?(/\A[A-Za-z_]\w*\z/) && !Module.public_method_defined?(name)
        # Optional parameters rather than *args, which would make an array
        # on every call (once per device of a robot file): Syskit's message
        # for up to three arguments, Ruby's beyond.
        define_singleton_method(name) do |first = NONE, second = NONE, third = NONE|
          unless first.equal?(NONE)
            given = [first, second, third].count { |a| !a.equal?(NONE) }
            raise ArgumentError, "expected 0 arguments, got #{given}"
          end

          @entries.fetch(name)
        end
      end
      constant = Namespace.constant_for(name)
      const_set(constant, value) if constant && !const_defined?(constant, false)
      value
    end
  end
end
