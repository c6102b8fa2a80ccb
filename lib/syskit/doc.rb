# frozen_string_literal: true

require 'syskit/doc/site'

module Syskit
  # `syskit doc`: the app's models and plans as a static HTML site (see
  # Doc::Site). The site is a renderer: it reads the loaded app and the
  # plans Network::Generator returns, and never plans on its own.
  module Doc
    module_function

    # Writes the site of +app+ (loaded) into +output+; returns a
    # Site::Result. +dot+: Graphviz's dot (found on PATH by default).
    def build(app, output:, robot: 'default', dot: dot_command)
      Site.new(app, robot: robot, dot: dot).write(output)
    end

    # Graphviz's dot on PATH, or nil.
    def dot_command
      Render::Svg.dot_command
    rescue Syskit::Error
      nil
    end
  end
end
