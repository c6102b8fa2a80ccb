# frozen_string_literal: true

require 'syskit/models/deployment'
require 'syskit/models/configured_deployment'

module Syskit
  # A deployment: the process running an oroGen deployment's tasks. Its
  # models (Syskit::Deployment and its submodels, see Models::Deployment)
  # each stand for one deployment spec; an instance is that process as a
  # robot configuration starts it, with its arguments (+on:+, the process
  # server; +name_mappings:+; +read_only:+ task names). Starting it is
  # Syskit's runtime, which the gem does not model.
  class Deployment
    extend Models::Deployment

    attr_reader :arguments

    def initialize(**arguments)
      @arguments = arguments.freeze
    end

    def model
      self.class
    end
  end
end
