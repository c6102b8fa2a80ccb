# frozen_string_literal: true

module Syskit
  module Test
    # Classes of Syskit that this gem does not have, because they belong
    # to Syskit's runtime or are the inside of its implementation. Under
    # Syskit's harness (syskit/test/self) each exists, so that the test
    # files that describe them load and the rest of each file runs; making
    # one (+.new+) skips the test, saying why. Outside the harness they do
    # not exist. A class the gem models is never replaced.
    module UnmodelledClasses
      RUNTIME = "needs Syskit's runtime (Roby/Orocos)"
      INTERNAL = "is the inside of Syskit's implementation, which its tests pin; not modelled by this gem"

      # Syskit's name => why the gem does not have it.
      CLASSES = {
        'Models::DynamicPortBinding' => RUNTIME,
        'Models::DynamicPortBinding::ValueResolver' => RUNTIME,
        'Models::DeploymentGroup' => RUNTIME,
        'NetworkGeneration::Async' => RUNTIME,
        'InputWriter' => RUNTIME,
        'OutputReader' => RUNTIME,
        'Component::DataAccessorInterface' => RUNTIME,
        'Models::SpecializationManager' => INTERNAL,
        'ConnectionGraph' => INTERNAL,
        'DataFlow' => INTERNAL,
        'DataFlow::ConcreteConnectionGraph' => INTERNAL,
        'InstanceSelection' => INTERNAL,
        'NetworkGeneration::MergeSolver' => INTERNAL,
        'NetworkGeneration::SystemNetworkDeployer' => INTERNAL,
        'NetworkGeneration::SystemNetworkGenerator' => INTERNAL,
        'NetworkGeneration::PortDynamics' => INTERNAL,
        'NetworkGeneration::PortDynamics::Trigger' => INTERNAL,
        'NetworkGeneration::DataFlowDynamics' => INTERNAL
      }.freeze

      # Defines the classes of CLASSES that Syskit does not have yet.
      def self.define_all
        CLASSES.each { |path, reason| define(path, reason) }
      end

      def self.define(path, reason)
        *parents, name = path.split('::')
        namespace = parents.inject(Syskit) do |mod, part|
          mod.const_defined?(part, false) ? mod.const_get(part, false) : mod.const_set(part, Module.new)
        end
        return if namespace.const_defined?(name, false)

        full_name = "Syskit::#{path}"
        namespace.const_set(name, Class.new do
          define_singleton_method(:new) { |*, **| raise Minitest::Skip, "#{full_name} #{reason}" }
        end)
      end
    end
  end
end
