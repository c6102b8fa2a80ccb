# frozen_string_literal: true

require_relative 'lsp_helper'

module Syskit
  # Every query at every few characters of every file of the example app:
  # whatever the cursor is on, the answer is of the type the server
  # expects, never an exception.
  class TestLSPQueriesEverywhere < Minitest::Test
    include SelfTest::LSPHelper

    def test_every_position_of_every_file_answers
      app = example_app
      queries = [LSP::Hover, LSP::Definition, LSP::Completion].map { |q| q.new(app) }
      answered = Hash.new(0)
      Dir.glob('**/*.{rb,orogen,yml}', base: EXAMPLE).each do |relative|
        path = example(relative)
        text = File.read(path)
        assert_kind_of Array, LSP::DocumentSymbols.new(app).of(path, text)
        each_position(text) do |line, character|
          queries.each { |q| answered[q.class] += 1 if answered?(q.at(path, text, line, character)) }
        end
      end
      # Each found something somewhere.
      assert_equal 3, answered.size, answered.inspect
    end

    def each_position(text, &)
      text.lines.each_with_index do |line, index|
        (0..line.chomp.size).step(4) { |character| yield(index, character) }
      end
    end

    def answered?(answer)
      assert(answer.nil? || answer.is_a?(String) || answer.is_a?(Array), answer.inspect)
      answer && !answer.empty?
    end
  end
end
