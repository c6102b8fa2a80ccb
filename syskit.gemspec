# frozen_string_literal: true

require_relative 'lib/syskit/version'

Gem::Specification.new do |spec|
  spec.name = 'syskit'
  spec.version = Syskit::VERSION
  spec.summary = "Describe a robot's devices and buses in Ruby and plan their component network"
  spec.description = <<~TEXT
    A standalone implementation of Syskit's model layer (Rock robotics): device and
    communication-bus models, drivers, robot definitions in profiles, and a network
    generator that turns a profile into a connection plan, with generators and
    minitest helpers.
  TEXT
  spec.authors = ['Syskit gem authors']
  spec.license = 'BSD-3-Clause' # see LICENSE
  # The gem has no site of its own: its homepage is the documentation of the
  # Syskit concepts it implements. Change it where the gem is published.
  spec.homepage = 'https://www.rock-robotics.org'
  spec.required_ruby_version = '>= 3.1'

  # The guides (doc/**/*.md) are read at run time too: syskit doc makes a
  # page of each, in the order the README lists them.
  spec.files = Dir['lib/**/*.rb', 'models/**/*', 'templates/**/*', 'bin/*', 'doc/**/*.md', 'README.md',
                   'CHANGELOG.md', 'LICENSE']
  spec.bindir = 'bin'
  spec.executables = ['syskit']
  spec.require_paths = ['lib']

  spec.add_dependency 'ffi', '~> 1.15'
  spec.add_dependency 'thor', '~> 1.2'

  spec.metadata['rubygems_mfa_required'] = 'true'
  spec.metadata['documentation_uri'] = 'https://www.rock-robotics.org/rock-and-syskit/'
end
