# frozen_string_literal: true

module Syskit
  module Network
    # What changed between two plans, given as the plain data of their JSON
    # documents (Plan#to_h, or a file written by `syskit plan --format
    # json`): per list of the plan, the entries added and removed and, for
    # an entry in both, each value that changed, by its path inside the
    # entry. The start order is a sequence: its steps are added, removed or
    # moved. A value: the renderers only read it.
    #
    # Lists are compared generically, entries matched by a key: a list the
    # plan gains (compositions) is compared as soon as it is in the
    # documents, by its entries' 'name' unless KEYS says otherwise.
    class PlanDiff
      # How entries of a list are matched, when not by 'name': the class
      # method that makes their key.
      KEYS = { 'connections' => :connection_key, 'frames' => :frame_key }.freeze
      # Lists that are sequences, whose entries move rather than change.
      SEQUENCES = %w[order].freeze
      # Values that say where something is declared, not what the plan is:
      # a line added above a declaration is no change to the robot.
      IGNORED = %w[declared_at].freeze

      # A value at +path+ (keys and entry keys inside an entry): +old+ or
      # +new+ is nil when the value was added or removed.
      Change = Struct.new(:path, :old, :new, keyword_init: true)
      # An entry in both plans whose values changed.
      Changed = Struct.new(:key, :entry, :changes, keyword_init: true)
      # A step of a sequence at another place (positions count from 1).
      Moved = Struct.new(:key, :old_position, :new_position, keyword_init: true)
      # What changed in one list.
      ListDiff = Struct.new(:name, :added, :removed, :changed, :moved, keyword_init: true) do
        def empty?
          added.empty? && removed.empty? && changed.empty? && moved.empty?
        end
      end

      attr_reader :old, :new, :lists

      # +old+, +new+: plans as plain data (hashes with string keys).
      def initialize(old, new)
        @old = old
        @new = new
        names = (list_names(old) + list_names(new)).uniq
        @lists = names.map { |name| diff_list(name, old.fetch(name, []), new.fetch(name, [])) }
      end

      # Whether the plans are the same (but for IGNORED values).
      def empty?
        old.values_at('profile', 'robot') == new.values_at('profile', 'robot') && lists.all?(&:empty?)
      end

      # The key of +entry+ of list +list+.
      def self.key(list, entry)
        return public_send(KEYS[list], entry) if KEYS.key?(list)
        return entry['name'] if entry.is_a?(Hash) && entry.key?('name')

        entry
      end

      # 'can0.n2k -> n2k.can_in': a connection is its two ends.
      def self.connection_key(conn)
        "#{conn.dig('from', 'task')}.#{conn.dig('from', 'port')} -> #{conn.dig('to', 'task')}.#{conn.dig('to', 'port')}"
      end

      # '181', '19F21123': a CAN frame is its id, in hex as candump writes it.
      def self.frame_key(frame)
        format(frame['extended'] ? '%08X' : '%03X', frame['id'])
      end

      # The diff as plain data, for --format json.
      def to_h
        {
          'old' => old.slice('profile', 'robot'), 'new' => new.slice('profile', 'robot'), 'identical' => empty?,
          'lists' => lists.to_h { |list| [list.name, list_hash(list)] }
        }
      end

      private

      # The lists of a plan document, in its order.
      def list_names(plan)
        plan.select { |_, value| value.is_a?(Array) }.keys
      end

      def diff_list(name, old_entries, new_entries)
        old_by_key = keyed(name, old_entries)
        new_by_key = keyed(name, new_entries)
        added = new_by_key.reject { |key, _| old_by_key.key?(key) }.values
        removed = old_by_key.reject { |key, _| new_by_key.key?(key) }.values
        changed = new_by_key.filter_map do |key, entry|
          next unless old_by_key.key?(key)

          changes = diff_values([], old_by_key[key], entry)
          Changed.new(key: key, entry: entry, changes: changes) unless changes.empty?
        end
        moved = SEQUENCES.include?(name) ? moves(old_by_key.keys, new_by_key.keys) : []
        ListDiff.new(name: name, added: added, removed: removed, changed: changed, moved: moved)
      end

      # Entries by key (entries of a sequence by their whole value).
      def keyed(name, entries)
        entries.to_h { |entry| [SEQUENCES.include?(name) ? entry : PlanDiff.key(name, entry), entry] }
      end

      # The changes between two values at +path+: hashes key by key, lists of
      # keyed entries (ports, frames) entry by entry, anything else whole.
      def diff_values(path, old, new)
        return [] if same?(old, new)
        return diff_calls(path, old, new) if calls?(path, old, new)
        return diff_hashes(path, old, new) if old.is_a?(Hash) && new.is_a?(Hash)
        return diff_entries(path, old, new) if keyed_list?(path.last, old) && keyed_list?(path.last, new)

        [Change.new(path: path, old: without_ignored(old), new: without_ignored(new))]
      end

      # Equal as plan values: NaN (an unknown value, as Rock writes it) is
      # the same as NaN, where Ruby's == says no.
      def same?(old, new)
        return true if old == new
        return old.nan? && new.nan? if old.is_a?(Float) && new.is_a?(Float)

        same_items?(old, new)
      end

      # Lists and hashes holding NaN, item by item.
      def same_items?(old, new)
        return false unless old.instance_of?(new.class) && old.size == new.size

        case old
        when Array then old.zip(new).all? { |a, b| same?(a, b) }
        when Hash then old.all? { |key, value| new.key?(key) && same?(value, new[key]) }
        else false
        end
      end

      # +value+ without the IGNORED keys of its hashes.
      def without_ignored(value)
        case value
        when Hash then value.except(*IGNORED).transform_values { |v| without_ignored(v) }
        when Array then value.map { |v| without_ignored(v) }
        else value
        end
      end

      # The operations a task's configure calls, as many before as after:
      # compared call by call (path +operations.2+), so that one changed
      # call is shown alone.
      def calls?(path, old, new)
        path.last == 'operations' && old.is_a?(Array) && new.is_a?(Array) && old.size == new.size
      end

      def diff_calls(path, old, new)
        old.zip(new).each_with_index.flat_map do |(before, after), i|
          next [] if same?(call_only(before), call_only(after))

          [Change.new(path: path + [(i + 1).to_s], old: before, new: after)]
        end
      end

      # A call without its argument names (files written before they were
      # kept have none).
      def call_only(call)
        call.is_a?(Hash) ? call.except('argument_names') : call
      end

      def diff_hashes(path, old, new)
        (old.keys | new.keys).flat_map do |key|
          next [] if IGNORED.include?(key)

          diff_values(path + [key], old[key], new[key])
        end
      end

      def diff_entries(path, old, new)
        list = path.last
        old_by_key = old.to_h { |e| [PlanDiff.key(list, e), e] }
        new_by_key = new.to_h { |e| [PlanDiff.key(list, e), e] }
        (old_by_key.keys | new_by_key.keys).flat_map do |key|
          diff_values(path + [key], old_by_key[key], new_by_key[key])
        end
      end

      # Lists whose entries have keys: hashes keyed by KEYS or by a name.
      def keyed_list?(name, value)
        value.is_a?(Array) && value.all? { |e| e.is_a?(Hash) && (KEYS.key?(name) || e.key?('name')) } &&
          value.map { |e| PlanDiff.key(name, e) }.uniq.size == value.size
      end

      # The steps in both sequences that are not in their longest common
      # order: those that moved.
      def moves(old_keys, new_keys)
        old_index = old_keys.each_with_index.to_h
        common = new_keys.select { |key| old_index.key?(key) }
        kept = longest_increasing(common.map { |key| old_index[key] }).to_h { |i| [old_keys[i], true] }
        new_index = new_keys.each_with_index.to_h
        common.reject { |key| kept[key] }.map do |key|
          Moved.new(key: key, old_position: old_index[key] + 1, new_position: new_index[key] + 1)
        end
      end

      # The longest increasing subsequence of +values+ (distinct integers),
      # in O(n log n) (patience sorting).
      def longest_increasing(values)
        tails = [] # index in values of the last element of the best run of each length
        previous = Array.new(values.size)
        values.each_with_index do |value, i|
          length = tails.bsearch_index { |t| values[t] >= value } || tails.size
          previous[i] = tails[length - 1] if length.positive?
          tails[length] = i
        end
        run = []
        i = tails.last
        while i
          run.unshift(values[i])
          i = previous[i]
        end
        run
      end

      def list_hash(list)
        {
          'added' => list.added, 'removed' => list.removed,
          'changed' => list.changed.map do |c|
            { 'key' => c.key, 'changes' => c.changes.map { |ch| ch.to_h.transform_keys(&:to_s) } }
          end,
          'moved' => list.moved.map do |m|
            { 'entry' => m.key, 'old_position' => m.old_position, 'new_position' => m.new_position }
          end
        }
      end
    end
  end
end
