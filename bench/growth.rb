# frozen_string_literal: true

module Syskit
  module Bench
    # The verdict on a scaling figure's growth exponent (log of the time
    # ratio over log of the size ratio: 1.0 is linear, 2.0 quadratic).
    # Issue 40's target is linear growth; an exponent up to LINEAR passes,
    # the slack being the shared machine's noise and the caches (a small
    # robot stays in them, a large one does not).
    module Growth
      LINEAR = 1.25

      module_function

      def exponent(small_size, small_time, large_size, large_time)
        Math.log(large_time / small_time.to_f) / Math.log(large_size / small_size.to_f)
      end

      # "linear (all <= 1.25): ok", or the exponents above it.
      def verdict(exponents_by_name)
        above = exponents_by_name.select { |_, e| e > LINEAR }
        return "linear (all <= #{LINEAR}): ok" if above.empty?

        "ABOVE LINEAR (> #{LINEAR}): #{above.map { |name, e| "#{name} #{format('%.2f', e)}" }.join(', ')}"
      end
    end
  end
end
