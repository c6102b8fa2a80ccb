# frozen_string_literal: true

module Syskit
  module CAN
    module Timing
      # How times and loads are written for people: milliseconds to the
      # microsecond, percentages to a tenth.
      module Format
        module_function

        # "3.25 ms": at most three decimals, trailing zeros dropped.
        def ms(seconds)
          "#{ms_value(seconds)} ms"
        end

        # "3.25", the number of ms alone (for tables).
        def ms_value(seconds)
          format('%.3f', (seconds * 1000).round(3).to_f).sub(/\.?0+\z/, '')
        end

        # "72.4 %"
        def percent(fraction)
          format('%.1f %%', (fraction * 100).to_f)
        end

        # "500 kbit/s", "1 Mbit/s", "83333 bit/s"
        def bitrate(bits_per_second)
          if (bits_per_second % 1_000_000).zero? then "#{bits_per_second / 1_000_000} Mbit/s"
          elsif (bits_per_second % 1000).zero? then "#{bits_per_second / 1000} kbit/s"
          else "#{bits_per_second} bit/s"
          end
        end
      end
    end
  end
end
