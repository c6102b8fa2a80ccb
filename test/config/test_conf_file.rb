# frozen_string_literal: true

require 'helper'
require 'minitest/mock'

module Syskit
  module Config
    # Configuration files read on their own: sections, their lines, and
    # what reading them costs.
    class TestConfFile < Minitest::Test
      def conf(text)
        dir = Dir.mktmpdir('syskit-conf')
        (@tmpdirs ||= []) << dir
        path = File.join(dir, 'lib::Task.yml')
        File.write(path, text)
        path
      end

      # Reading a file hands YAML each section's own text once: its size,
      # not the square of its sections (20,000 sections took seconds
      # when each was padded with the lines before it).
      def test_reading_a_file_parses_each_section_once
        text = +"--- name:default\nrate: 1\n"
        2000.times { |i| text << "--- name:s#{i}\nrate: #{i}\n" }
        parsed = 0
        safe_load = Psych.method(:safe_load)
        counting = lambda do |yaml, **options|
          parsed += yaml.bytesize
          safe_load.call(yaml, **options)
        end
        file = Psych.stub(:safe_load, counting) { ConfFile.new(conf(text)) }
        assert_equal 2001, file.sections.size
        assert_operator parsed, :<=, text.bytesize
        assert_equal({ 'rate' => 1999 }, file.merged(%w[default s1999], location: nil))
      end

      def test_lines_of_a_file_without_header_count_from_one
        path = conf("rate: 1\nlimits: *a\n")
        error = assert_raises(ConfigurationError) { ConfFile.new(path) }
        assert_match(/YAML aliases are not allowed/, error.message)
        assert_equal 2, error.location.lineno
        error = assert_raises(ConfigurationError) { ConfFile.new(conf("rate: 1\nlimits: [1\n")) }
        assert_equal 2, error.location.lineno
      end

      def test_lines_of_a_section_count_from_its_header
        error = assert_raises(ConfigurationError) { ConfFile.new(conf("--- name:a\nrate: 1\n--- name:b\nx: [1\n")) }
        assert_match(/invalid YAML/, error.message)
        assert_equal 4, error.location.lineno
        file = ConfFile.new(conf("# a comment\n--- name:default\nrate: 1\n--- name:b\n\nrate: 2\n"))
        assert_equal [3, 6], [file.location_of('rate', ['default']).lineno, file.location_of('rate', %w[b]).lineno]
      end

      def test_a_date_names_the_property_it_is_given_to
        error = assert_raises(ConfigurationError) { ConfFile.new(conf("--- name:a\nrate: 1\nsince: 2024-01-31\n")) }
        assert_equal "property 'since': 2024-01-31 is read by YAML as a date, which is not a property value",
                     error.message
        assert_equal [3, "quote it to make it a string: since: '2024-01-31'"], [error.location.lineno, error.hint]
        error = assert_raises(ConfigurationError) { ConfFile.new(conf("limits:\n  from: 2024-01-31 08:00:00\n")) }
        assert_equal "property 'limits' (from): 2024-01-31 08:00:00 is read by YAML as a time, which is not a " \
                     'property value', error.message
        assert_equal 2, error.location.lineno
      end

      def test_a_default_section_without_header_declared_again
        error = assert_raises(ConfigurationError) { ConfFile.new(conf("rate: 1\n--- name:default\nrate: 2\n")) }
        assert_equal "section 'default' is declared twice (first at the top of the file)", error.message
        assert_equal 2, error.location.lineno
      end
    end
  end
end
