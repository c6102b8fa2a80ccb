# frozen_string_literal: true

require 'helper'

module Syskit
  module Generators
    # Text from users lands in generated Ruby files on comment lines only:
    # a line break in it never starts a line of live code.
    class TestTemplate < Minitest::Test
      SPEC = <<~RUBY
        name 'sensors'
        import_types_from 'canbus'

        task_context 'Task' do
          doc "Reads a CAN sensor\\nFile.write('pwned', 'the doc ran')\\r\\n\\n  and more"
          output_port 'samples', '/canbus/Message'
        end
      RUBY

      def test_a_multi_line_doc_becomes_comment_lines
        root = my_app(nil, 'models/orogen/sensors.orogen' => SPEC)
        _, err, status = run_cli('gen', 'orogen', 'sensors', '--app', root)
        assert_equal 0, status, err
        generated = File.read(File.join(root, 'models/orogen/sensors.rb'))
        assert_includes generated, "# Reads a CAN sensor\n# File.write('pwned', 'the doc ran')\n#\n#   and more\n" \
                                   'Syskit.extend_model OroGen.sensors.Task do'
        out, err, status = run_cli('check', '--app', root)
        assert_equal 0, status, out + err
        refute File.exist?(File.join(GEM_ROOT, 'pwned'))
        refute File.exist?(File.join(root, 'pwned'))
      end

      def test_values_with_line_breaks_are_refused_unless_they_are_comments
        error = assert_raises(GeneratorError) do
          Template.render('app_syskit_yml', app_name: "Robot\nsystem('x')", dir_name: 'robot', acronyms: [])
        end
        assert_match(/a generated line would be cut by a line break in "Robot\\nsystem/, error.message)
        assert_equal "# a\n# b", Template.comment("a\nb")
        rendered = Template.render('app_syskit_yml', app_name: 'Robot', dir_name: 'robot', acronyms: [])
        assert_match(/^name: Robot$/, rendered)
      end
    end
  end
end
