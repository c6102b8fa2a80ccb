# frozen_string_literal: true

module Syskit
  module Test
    # Classes of Syskit that this gem does not have, because they belong
    # to Syskit's runtime or are the inside of its implementation. Under
    # Syskit's harness (syskit/test/self) each exists, so that the test
    # files that describe them load and the rest of each file runs; making
    # one (+.new+) skips the test, saying why. Outside the harness they do
    # not exist. A class the gem models is never replaced (see
    # add_factories).
    module UnmodelledClasses
      RUNTIME = RuntimeOnly::REASON
      INTERNAL = "is the inside of Syskit's implementation, which its tests pin; not modelled by this gem"

      # Syskit's name (under Syskit, or from the top level with a leading
      # +::+: Roby's, oroGen's and concurrent-ruby's classes that Syskit's
      # tests reach) => why the gem does not have it. Syskit's tests reach
      # Roby, Orocos and Typelib through the stand-ins Compat installs.
      CLASSES = {
        'RobyApp::Configuration' => RUNTIME,
        'RobyApp::UnmanagedTasksManager' => RUNTIME,
        'RobyApp::UnmanagedProcess' => RUNTIME,
        'Compat::Orocos::RubyTasks::ProcessManager' => RUNTIME,
        'Compat::Orocos::RubyTasks::TaskContext' => RUNTIME,
        'Compat::Orocos::TaskContext' => RUNTIME,
        'Compat::Orocos::Property' => RUNTIME,
        'Compat::Roby::DRoby::Marshal' => RUNTIME,
        'Compat::Roby::DRoby::Unmarshallable' => RUNTIME,
        'Compat::Typelib::CXXRegistry' => RUNTIME,
        '::OroGen::Loaders::Base' => RUNTIME,
        '::Concurrent::CyclicBarrier' => RUNTIME,
        '::Concurrent::IVar' => RUNTIME,
        '::Concurrent::Event' => RUNTIME,
        'Compat::Roby::EventGenerator' => RUNTIME,
        'Compat::Roby::StateSpace' => RUNTIME,
        'Compat::Roby::Test::ExecutionExpectations::UnexpectedErrors' => RUNTIME,
        'DynamicPortBinding' => RUNTIME,
        'DynamicPortBinding::Accessor' => RUNTIME,
        'DynamicPortBinding::OutputReader' => RUNTIME,
        'DynamicPortBinding::BoundOutputReader' => RUNTIME,
        'DynamicPortBinding::InputWriter' => RUNTIME,
        'DynamicPortBinding::BoundInputWriter' => RUNTIME,
        'Models::DynamicPortBinding' => RUNTIME,
        'Models::DynamicPortBinding::ValueResolver' => RUNTIME,
        'NetworkGeneration::Async' => RUNTIME,
        'InputWriter' => RUNTIME,
        'OutputReader' => RUNTIME,
        'Component::DataAccessorInterface' => RUNTIME,
        'ConnectionGraph' => INTERNAL,
        'DataFlow' => INTERNAL,
        'DataFlow::ConcreteConnectionGraph' => INTERNAL,
        'NetworkGeneration::MergeSolver' => INTERNAL,
        'NetworkGeneration::SystemNetworkDeployer' => INTERNAL,
        'NetworkGeneration::SystemNetworkGenerator' => INTERNAL,
        'NetworkGeneration::DataFlowDynamics' => INTERNAL
      }.freeze

      # How Syskit's tests make an instance of these classes: +.new+, and
      # the factories of Models::DynamicPortBinding.
      FACTORIES = %i[new create create_from_component_port create_from_matcher].freeze

      # Those of CLASSES that are modules in Syskit (Roby's): an object is
      # extended with one, which skips.
      MODULES = %w[Compat::Roby::DRoby::Unmarshallable].freeze

      # Defines the classes of CLASSES that Syskit does not have yet.
      def self.define_all
        CLASSES.each { |path, reason| define(path, reason) }
      end

      def self.define(path, reason)
        root = path.start_with?('::') ? Object : Syskit
        *parents, name = path.delete_prefix('::').split('::')
        namespace = parents.inject(root) do |mod, part|
          mod.const_defined?(part, false) ? mod.const_get(part, false) : mod.const_set(part, Module.new)
        end
        full_name = path.start_with?('::') ? path.delete_prefix('::') : "Syskit::#{path}"
        if namespace.const_defined?(name, false)
          return add_factories(namespace.const_get(name, false), full_name, reason)
        end

        stand_in = MODULES.include?(path) ? stand_in_module(full_name, reason) : stand_in(full_name, reason)
        namespace.const_set(name, stand_in)
      end

      # Where the gem has the class (or module) but not the ways Syskit's
      # tests make one of Syskit's (Models::DynamicPortBinding.create: the
      # gem's holds the data accessors of component models), those skip.
      def self.add_factories(existing, full_name, reason)
        FACTORIES.each do |factory|
          next if existing.respond_to?(factory)

          existing.define_singleton_method(factory) { |*, **| raise Minitest::Skip, "#{full_name}.#{factory} #{reason}" }
        end
      end

      def self.stand_in(full_name, reason)
        Class.new do
          FACTORIES.each do |factory|
            define_singleton_method(factory) { |*, **| raise Minitest::Skip, "#{full_name} #{reason}" }
          end
        end
      end

      def self.stand_in_module(full_name, reason)
        Module.new do
          define_singleton_method(:extended) { |_object| raise Minitest::Skip, "#{full_name} #{reason}" }
        end
      end
    end
  end
end
