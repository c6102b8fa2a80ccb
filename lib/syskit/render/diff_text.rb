# frozen_string_literal: true

require 'syskit/naming'
require 'syskit/render/text'

module Syskit
  module Render
    # A Network::PlanDiff for people reviewing a change: per list of the
    # plan, a count, then '+' for an entry added, '-' removed, '~' changed
    # (each changed value with its path in the entry, old -> new), and the
    # steps that moved in the start order. Values are written as the text
    # plan writes them (CAN ids and masks in hex).
    module DiffText
      # What follows the key of an added or removed entry, by list: a list
      # without one shows its key alone.
      SUMMARIES = {
        'tasks' => ->(t) { [t['model'], ("deployment #{t['deployment']}" if t['deployment'])] },
        'devices' => ->(d) { [d['model'], ("task #{d['task']}" if d['task']), ("bus #{d['bus']}" if d['bus'])] },
        'connections' => ->(c) { [c['type'], policy(c['policy'])] },
        'buses' => ->(b) { [("bitrate #{b['bitrate']}" if b['bitrate'])] },
        'compositions' => ->(c) { [c['model'], ("children #{c['children'].values.join(' ')}" if c['children']&.any?)] }
      }.freeze

      module_function

      # The diff as text; +old_name+, +new_name+ say where the plans come from.
      def render(diff, old_name:, new_name:)
        text = [*header(diff, old_name, new_name), '']
        return "#{text.join("\n")}the plans are the same\n" if diff.empty?

        diff.lists.reject(&:empty?).each { |list| text.concat(list_lines(list), ['']) }
        "#{text.join("\n").chomp}\n"
      end

      def header(diff, old_name, new_name)
        old = diff.old
        new = diff.new
        lines = ["Plan diff of #{new['profile']} on robot '#{new['robot']}'", "  old: #{old_name}",
                 "  new: #{new_name}"]
        %w[profile robot].each do |key|
          lines << "  #{key}: #{old[key]} -> #{new[key]}" unless old[key] == new[key]
        end
        lines
      end

      def list_lines(list)
        lines = ["#{Naming.camelize(list.name)}: #{counts(list)}"]
        lines.concat(list.added.map { |e| "  + #{entry_line(list.name, e)}" })
        lines.concat(list.removed.map { |e| "  - #{entry_line(list.name, e)}" })
        list.changed.each do |changed|
          lines << "  ~ #{changed.key}"
          lines.concat(changed.changes.map { |c| "      #{change_line(c)}" })
        end
        lines.concat(list.moved.map { |m| "  #{step(m.key)}: step #{m.old_position} -> #{m.new_position}" })
      end

      # '1 added, 2 changed'
      def counts(list)
        { 'added' => list.added, 'removed' => list.removed, 'changed' => list.changed, 'moved' => list.moved }
          .reject { |_, entries| entries.empty? }.map { |what, entries| "#{entries.size} #{what}" }.join(', ')
      end

      def entry_line(list, entry)
        return step(entry) if list == 'order'

        summary = SUMMARIES.fetch(list, ->(_) { [] }).call(entry).compact
        key = Network::PlanDiff.key(list, entry)
        summary.empty? ? key.to_s : "#{key}  #{summary.join(', ')}"
      end

      def change_line(change)
        path = change.path.join('.')
        if change.old.nil? then "#{path}: added #{value(change.new, change.path)}"
        elsif change.new.nil? then "#{path}: removed #{value(change.old, change.path)}"
        else "#{path}: #{value(change.old, change.path)} -> #{value(change.new, change.path)}"
        end
      end

      # A step of the start order: 'configure can0'.
      def step(entry)
        entry.is_a?(Hash) ? entry.values.join(' ') : entry.to_s
      end

      def policy(policy)
        return unless policy

        [policy['type'], policy['size']].compact.join(' ')
      end

      # A value at +path+: CAN ids in hex, an entry of a keyed list without
      # the key its path shows, operation calls as they were written.
      def value(value, path)
        return value.map { |call| call_text(call) }.join(', ') if path.last == 'operations' && value.is_a?(Array)
        return call_text(value) if path[-2] == 'operations'

        value = value.reject { |k, v| k == 'name' && v == path.last } if value.is_a?(Hash)
        Text.plain(value, +'', ids: path.any? { |name| Output.id_name?(name) })
      end

      # watch("sensor", 0x100, 0x7FF): ids in hex, as the plan writes them,
      # when the file names the arguments.
      def call_text(call)
        return Text.plain(call, +'') unless call.is_a?(Hash) && call['arguments'].is_a?(Array)

        names = call['argument_names'] || []
        arguments = call['arguments'].each_with_index.map do |arg, i|
          Text.plain(arg, +'', ids: Output.id_name?(names[i]))
        end
        "#{call['name']}(#{arguments.join(', ')})"
      end
    end
  end
end
