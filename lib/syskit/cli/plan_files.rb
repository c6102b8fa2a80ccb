# frozen_string_literal: true

require 'json'
require 'syskit/network/plan_diff'
require 'syskit/render/diff_text'
require 'syskit/render/json'

module Syskit
  class CLI < Thor
    # What `syskit diff` and `syskit plan --diff` do between parsing their
    # options and printing: read plans written by `syskit plan --format
    # json`, compare them, render the difference.
    module PlanFiles
      HINT = 'a plan file is what syskit plan PROFILE --format json > plan.json writes'

      module_function

      # The plan document in the file at +path+ (plain data), or a located
      # error saying why it is not one.
      def read(path)
        raise FileLoadError.new("no plan file '#{path}'", hint: HINT) unless File.file?(path)

        location = Location.new(File.expand_path(path), nil)
        text = UserFile.read(path)
        raise FileLoadError.new('this plan file is empty', location: location, hint: HINT) if text.strip.empty?

        plan = ::JSON.parse(text, allow_nan: true)
        return plan if plan?(plan)

        raise FileLoadError.new('this is JSON but not a plan (it has no profile, robot and tasks)',
                                location: location, hint: HINT)
      rescue ::JSON::ParserError => e
        why = e.message.lines.first.strip.sub(/\A\d+: /, '')[0, 200]
        raise FileLoadError.new("this is not a JSON plan: #{why}", location: location, hint: HINT)
      end

      def plan?(plan)
        plan.is_a?(Hash) && plan['profile'].is_a?(String) && plan['robot'].is_a?(String) && plan['tasks'].is_a?(Array)
      end

      # The plain data of a generated plan, as a plan file holds it.
      def plain(plan)
        ::JSON.parse(Render::JSON.render(plan))
      end

      # The diff of +old+ and +new+ (plan documents) in +format+.
      def render(old, new, format, old_name:, new_name:)
        diff = Network::PlanDiff.new(old, new)
        text = if format == 'json'
                 Render::JSON.pretty(diff.to_h)
               else
                 Render::DiffText.render(diff, old_name: old_name, new_name: new_name)
               end
        [diff, text]
      end
    end
  end
end
