# frozen_string_literal: true

require_relative '../helper'
require 'syskit/lsp'

module Syskit
  # Problems as the editor's diagnostics.
  class TestLSPDiagnostics < Minitest::Test
    # The satellite is one character, two UTF-16 code units.
    TEXT = "first\n    device(Devices::GPS, as: 'x') # \u{1F6F0}\n"

    def by_file(problems, fallback: '/app/models/opened.rb')
      LSP::Diagnostics.by_file(problems, fallback_path: fallback, text_of: ->(_path) { TEXT })
    end

    def test_a_range_covers_the_written_part_of_the_line_in_utf16_code_units
      error = Error.new('unknown model', location: Location.new('/app/models/x.rb', 2), hint: 'declare it')
      diagnostic, = by_file([error])['/app/models/x.rb']
      assert_equal({ start: { line: 1, character: 4 }, end: { line: 1, character: 38 } }, diagnostic[:range])
      assert_equal [1, 'Error', 'unknown model'], diagnostic.values_at(:severity, :code, :message)
      assert_equal 'hint: declare it', diagnostic[:relatedInformation].first[:message]
    end

    def test_warnings_without_hint_and_problems_without_location
      warning = Warning.new('not modelled', location: Location.new('/app/models/x.rb', 9))
      unlocated = Error.new('the app has no profile')
      result = by_file([warning, unlocated])
      diagnostic, = result['/app/models/x.rb']
      assert_equal 2, diagnostic[:severity]
      refute diagnostic.key?(:relatedInformation)
      assert_equal 0, diagnostic[:range][:start][:line], 'a line past the end is the first line'
      assert_equal(['the app has no profile'], result['/app/models/opened.rb'].map { |d| d[:message] })
    end
  end
end
