# frozen_string_literal: true

module Syskit
  module Compat
    # oroGen's specification classes that Syskit's tests make models with.
    module OrogenSpec
      # +OroGen::Spec::Project.new(loader)+: the project an oroGen model
      # made in Ruby belongs to; +project.name 'lib'+ names it.
      class Project
        def initialize(loader = nil)
          @loader = loader
        end

        def name(value = nil)
          return @name if value.nil?

          @name = value.to_s
        end

        def to_s
          "OroGen::Spec::Project(#{@name})"
        end
      end

      # +OroGen::Spec::TaskContext.new(project, 'lib::Task')+: an oroGen
      # task model made in Ruby (see Orogen::ModelView.define).
      module TaskContext
        def self.new(project = nil, name = nil, subclasses: nil)
          Orogen::ModelView.define(name, project: project, subclasses: subclasses)
        end
      end
    end
  end
end
