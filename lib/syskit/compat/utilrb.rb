# frozen_string_literal: true

# What a Rock app always has loaded, and its files therefore use without a
# require: Ruby's Set, Logger and Socket, and what Rock's utilrb adds to
# Ruby (the module loggers below, Kernel.validate_options).
require 'set'
require 'logger'
# Loaded when a file first names one of its classes: 3 ms of every
# command's start-up that most apps never use.
%i[Socket BasicSocket IPSocket TCPSocket TCPServer UDPSocket UNIXSocket UNIXServer Addrinfo].each do |name|
  Object.autoload(name, 'socket') unless Object.const_defined?(name, false)
end

module Syskit
  module Compat
    # utilrb's module loggers, as bundles declare them:
    #
    #   module RockAUV
    #     extend Logger::Root('RockAUV', Logger::INFO)   # RockAUV.info '...'
    #     module Control
    #       extend Logger::Hierarchy                       # RockAUV's logger
    #     end
    #   end
    #
    # They write to stderr, as the logging of Robot does.
    module UtilrbLogger
      # +debug+ ... +fatal+ on whatever has a +logger+.
      module Forward
        %i[debug info warn error fatal].each do |level|
          define_method(level) { |message = nil, &block| logger.public_send(level, message, &block) }
        end

        def log_level=(level)
          logger.level = level
        end
      end

      # +logger+ is the one of the first enclosing module that has one (by
      # name: RockAUV::Control -> RockAUV); an instance uses its class's.
      module Hierarchy
        include Forward

        def logger
          @logger ||=
            if is_a?(Module) then Hierarchy.parent_logger(self)
            elsif self.class.respond_to?(:logger) then self.class.logger
            else Hierarchy.parent_logger(self.class)
            end
        end

        def self.parent_logger(mod)
          names = mod.name.to_s.split('::')
          until names.empty?
            names.pop
            parent = names.empty? ? nil : Object.const_get(names.join('::'))
            return parent.logger if parent.respond_to?(:logger)
          end
          Hierarchy.default
        end

        def self.default
          @default ||= UtilrbLogger.make('Rock', ::Logger::WARN)
        end
      end

      # A logger named +progname+ at +level+, writing to stderr.
      def self.make(progname, level)
        logger = ::Logger.new($stderr, progname: progname.to_s, level: level)
        logger.formatter = ->(severity, _time, name, message) { "#{name} #{severity}: #{message}\n" }
        logger
      end

      # utilrb's +Logger.Root(name, level)+: a module giving what extends it
      # a logger of its own.
      def self.root(progname, level)
        Module.new do
          include Forward

          define_method(:logger) { @logger ||= UtilrbLogger.make(progname, level) }
        end
      end
    end

    # utilrb's option checks (+Kernel.validate_options opts, :a, b: 1+):
    # unknown keys are an ArgumentError, defaults fill missing ones;
    # filter_options splits what is known from the rest.
    module UtilrbOptions
      def validate_options(options, *known)
        options, rest = filter_options(options, *known)
        unless rest.empty?
          raise ArgumentError, "unknown options #{rest.keys.map(&:inspect).join(', ')}, " \
                               "known: #{UtilrbOptions.known_keys(known).map(&:inspect).join(', ')}"
        end

        options
      end

      def filter_options(options, *known)
        options = (options || {}).transform_keys { |k| k.respond_to?(:to_sym) ? k.to_sym : k }
        keys = UtilrbOptions.known_keys(known)
        defaults = known.last.is_a?(Hash) ? known.last.transform_keys(&:to_sym) : {}
        filtered = defaults.merge(options.slice(*keys))
        [filtered, options.except(*keys)]
      end

      def self.known_keys(known)
        known.flat_map { |k| k.is_a?(Hash) ? k.keys : Array(k) }.map(&:to_sym)
      end
    end
  end
end

# utilrb's name, a method named like a class (Logger::Root('Name', Logger::INFO)).
Logger.define_singleton_method(:Root) { |progname, level| Syskit::Compat::UtilrbLogger.root(progname, level) } # rubocop:disable Naming/MethodName
Logger.const_set(:Forward, Syskit::Compat::UtilrbLogger::Forward) unless Logger.const_defined?(:Forward, false)
Logger.const_set(:Hierarchy, Syskit::Compat::UtilrbLogger::Hierarchy) unless Logger.const_defined?(:Hierarchy, false)
# Kernel.validate_options, and validate_options as a private method of
# every object, as utilrb has them.
Kernel.extend(Syskit::Compat::UtilrbOptions)
Kernel.include(Syskit::Compat::UtilrbOptions)
Kernel.send(:private, :validate_options, :filter_options)
