# frozen_string_literal: true

require 'syskit/property'

module Syskit
  # The +properties+ of a task: its Property objects by name
  # (+properties['period']+), and a reader and a writer per property
  # (+properties.period = 0.1+), checking values against the property's
  # type; +raw_period+ reads and writes the same value (Syskit's typed
  # access), and +properties.period { |v| v * 2 }+ updates it.
  class Properties
    include Enumerable

    # The properties class of +task_model+, with the accessors of each of
    # its properties. A property named like a public method of this class
    # (names, to_h, ...) keeps the method; it is read with
    # properties['name'].read.
    def self.for(task_model)
      klass = Class.new(self)
      klass.instance_variable_set(:@task_model, task_model)
      task_model.property_declarations.each_key { |name| klass.define_accessors(name) }
      klass
    end

    class << self
      attr_reader :task_model

      def sorted_names
        @sorted_names ||= task_model.property_declarations.keys.sort.freeze
      end

      # The properties of +task+ (nil: of no task, as a configuration
      # section is checked on), at their initial values.
      def initial(task = nil)
        properties = {}
        task_model.property_declarations.each do |name, declaration|
          properties[name.to_s] = Property.new(declaration, task_model, task)
        end
        new(task, properties)
      end

      # Defines +name+, +name=+, +raw_name+ and +raw_name=+, unless taken.
      def define_accessors(name)
        define_reader(name, :read)
        define_reader("raw_#{name}", :raw_read, name)
        define_writer(name, :write)
        define_writer("raw_#{name}", :raw_write, name)
      end

      private

      def define_reader(method, access, name = method)
        # Kernel's private methods (test, format...) are no method of
        # properties: a property may be called so.
        return if method_defined?(method)

        define_method(method) { |&block| block ? update(name, access, &block) : @properties[name].public_send(access) }
      end

      def define_writer(method, access, name = method)
        return if method_defined?("#{method}=")

        define_method("#{method}=") { |value| @properties[name].public_send(access, value) }
      end
    end

    # The task they are the properties of.
    attr_reader :task

    # +properties+: Property objects by name (strings; see .initial). On
    # Properties itself (not the class of a task model) the accessors are
    # made for these.
    def initialize(task, properties)
      @task = task
      @properties = properties
      return unless instance_of?(Properties)

      @properties.each_key { |name| singleton_class.define_accessors(name) }
    end

    # Enumerates the Property objects.
    def each(&)
      return enum_for(__method__) unless block_given?

      @properties.each_value(&)
    end

    def include?(name)
      @properties.key?(name.to_s)
    end

    # The property called +name+, nil when there is none.
    def [](name)
      @properties[name.to_s]
    end

    def declarations
      self.class.task_model.property_declarations
    end

    # Why properties.+name+ does not exist, for typos in configure methods.
    def explain_missing(name)
      name = name.delete_suffix('=')
      ["#{owner_name} has no property '#{name}'#{Naming.did_you_mean(name, names)}",
       "its properties are #{names.sort.join(', ').then { |s| s.empty? ? '(none)' : s }}"]
    end

    def names
      @properties.keys
    end

    # Values as plain data (hashes, arrays, numbers, strings), sorted by name.
    def to_plain
      plain = {}
      self.class.sorted_names.each { |k| plain[k] = @properties[k].to_plain }
      plain
    end

    # The values by name.
    def to_h
      @properties.transform_values(&:value)
    end

    private

    # +properties.name { |value| new_value }+: reads, then writes what the
    # block returns.
    def update(name, access, &)
      property = @properties[name]
      writer = access == :raw_read ? :raw_write : :write
      property.public_send(writer, yield(property.public_send(access)))
    end

    def owner_name
      task ? task.model.name : self.class.task_model&.name
    end
  end
end
