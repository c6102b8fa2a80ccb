# frozen_string_literal: true

# The statements of .orogen files, one file per level of the file.
require 'syskit/orogen/spec_dsl/statements_dsl'
require 'syskit/orogen/spec_dsl/typekit_dsl'
require 'syskit/orogen/spec_dsl/project_dsl'
require 'syskit/orogen/stream_plugins'
require 'syskit/orogen/spec_dsl/task_context_dsl'
require 'syskit/orogen/spec_dsl/stream_plugins_dsl'
require 'syskit/orogen/spec_dsl/deployment_dsl'
