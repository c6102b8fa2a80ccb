# frozen_string_literal: true

# Suggestions for misspelled names. Loaded here once: a require in the
# method would cost a search of the loaded features each time, which Ruby
# re-indexes whenever an app marks one of its files loaded.
require 'did_you_mean'

module Syskit
  # Conversions between the path form users type (gps/ublox/f9) and the
  # constant form models are named with (GPS::Ublox::F9).
  module Naming
    CONSTANT_NAME = /\A[A-Z][A-Za-z0-9_]*\z/

    module_function

    def constant_name?(name)
      CONSTANT_NAME.match?(name.to_s)
    end

    # 'gps' -> 'GPS' (when GPS is an acronym), 'gig_e' -> 'GigE', 'f9' -> 'F9'.
    # A segment already in constant form is kept as it is.
    def camelize(segment, acronyms = [])
      return segment if constant_name?(segment) && !segment.include?('_')

      segment.split('_').reject(&:empty?).map do |word|
        acronyms.find { |a| a.casecmp?(word) } || (word[0].upcase + word[1..])
      end.join
    end

    # 'GPS' -> 'gps', 'GigE' -> 'gig_e', 'IMUSensor' -> 'imu_sensor', 'F9' -> 'f9'.
    def underscore(constant)
      constant.to_s
              .gsub(/([A-Z]+)([A-Z][a-z])/, '\1_\2')
              .gsub(/([a-z\d])([A-Z])/, '\1_\2')
              .downcase
    end

    # Suggestions for a misspelled +name+ among +candidates+.
    def suggest(name, candidates)
      DidYouMean::SpellChecker.new(dictionary: candidates.map(&:to_s)).correct(name.to_s)
    end

    # "a, b, c" or, past +max+ items, "a, b, c and 997 more": lists that a
    # message per device repeats (the deployed tasks it could use) stay
    # short, so that the output grows with the devices, not their pairs.
    def enumerate(items, max: 10)
      shown = items.first(max).join(', ')
      items.size > max ? "#{shown} and #{items.size - max} more" : shown
    end

    # "1 frame", "2 frames"
    def count(number, word)
      "#{number} #{word}#{'s' unless number == 1}"
    end

    # " (did you mean 'x'?)" or an empty string.
    # How DSL files name a model: +OroGen.lib.Task+ for a task context of
    # a task library, the constant name otherwise.
    def dsl_reference(model)
      name = model.name.to_s
      from_library = model.is_a?(Class) && model < Syskit::TaskContext && model.spec&.library
      return name unless from_library

      "OroGen.#{name.gsub('::', '.')}"
    end

    def did_you_mean(name, candidates)
      found = suggest(name, candidates)
      found.empty? ? '' : " (did you mean #{found.map { |s| "'#{s}'" }.join(' or ')}?)"
    end
  end
end
