# frozen_string_literal: true

require 'helper'

module Syskit
  # Misuses of the modelling DSL are Syskit's located errors and Ruby
  # ArgumentErrors at once, as Syskit raises ArgumentError for them.
  class TestDeclarationErrors < Minitest::Test
    def test_a_misuse_is_an_argument_error_that_keeps_its_location_and_hint
      load_app(write_app({}))
      srv = DataService.new_submodel(name: 'Ranging')
      line = __LINE__ + 1
      error = assert_raises(ArgumentError) { Composition.new_submodel { add srv } }
      assert_kind_of DeclarationError, error
      file = File.expand_path(__FILE__)
      assert_equal "#{file}:#{line}", error.location.to_s
      assert_equal "#{file}:#{line}: add needs a child name (as:)\n  hint: write add Ranging, as: 'name'",
                   error.report
    end

    def test_rescue_syskit_error_still_catches_it
      load_app(write_app({}))
      caught = begin
        Composition.new_submodel { add DataService.new_submodel(name: 'Sonar') }
      rescue Syskit::Error => e
        e
      end
      assert_kind_of DeclarationError, caught
    end

    def test_syskit_check_reports_it_located_without_a_backtrace
      root = write_app({ 'models/compositions/bad.rb' => <<~RUBY })
        module TestApp
          class Ranging < Syskit::Composition
            add Syskit::DataService.new_submodel(name: 'Ranger')
          end
        end
      RUBY
      out, err, status = run_cli('check', '--app', root)
      assert_equal 1, status, err
      assert_match(%r{^models/compositions/bad.rb:3: add needs a child name \(as:\)$}, out)
      assert_match(/^  hint: write add Ranger, as: 'name'$/, out)
      refute_match(/\.rb:\d+:in `/, out + err)
    end
  end
end
