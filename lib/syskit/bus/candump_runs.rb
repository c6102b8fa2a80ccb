# frozen_string_literal: true

module Syskit
  module Bus
    # The regexps of the lines CandumpLog#read reads by position, a run of
    # lines at a time: lines as candump -l writes them for the interface
    # read (@interface, chosen by the first frame).
    module CandumpRuns
      # A run of one second shorter than this many lines (a quiet bus) is
      # followed by a run of lines of any second (see CandumpLog#read).
      SHORT_RUN = 8
      # A line as candump -l writes it (see #fast_line), with the text of
      # its seconds and of the interface read: data of 0 to 8 bytes, a
      # remote request (R, R0 to R8), or a CAN FD frame (#, its flags
      # digit, data of one of Frame::CANFD_LENGTHS). Its groups capture
      # nothing: #fast_runs refers to the seconds as group 1.
      FAST_LINE_TEXT = '\(%<seconds>s\.\d{6}\) %<interface>s (?:[0-7]\h\h|[01]\h{7})#(?:(?:\h\h){0,8}|R[0-8]?|' \
                       '#\h(?:(?:\h\h){0,8}|(?:\h{8}){3,6}|(?:\h{8}){8}|(?:\h{8}){12}|(?:\h{8}){16}))\n'

      private

      # The regexp of lines as candump -l writes them for the interface
      # read, which CandumpLog#read reads by position: 10 digits of
      # seconds, a standard id up to 7FF or an extended one without the
      # error flag, and what FAST_LINE_TEXT allows after them (nil until
      # the interface is known).
      def fast_line
        return unless @interface&.ascii_only?

        @fast_line ||= /\A#{format(FAST_LINE_TEXT, seconds: '\d{10}', interface: Regexp.escape(@interface))}\z/
      end

      # One or more such lines in a row from where the match starts, all of
      # the same second: the first line captures its seconds, the others
      # must repeat them (a back reference), so that CandumpLog#read
      # converts the seconds once a run instead of once a line. A run ends
      # where the second changes (every few thousand lines of a busy bus).
      def fast_runs
        @fast_runs ||= begin
          interface = Regexp.escape(@interface)
          first = format(FAST_LINE_TEXT, seconds: '(\d{10})', interface: interface)
          same = format(FAST_LINE_TEXT, seconds: '\1', interface: interface)
          /\G#{first}(?:#{same})*/
        end
      end

      # One or more such lines in a row, of any seconds (a quiet bus's:
      # see CandumpLog#read).
      def fast_mixed_runs
        @fast_mixed_runs ||= /\G(?:#{format(FAST_LINE_TEXT, seconds: '\d{10}', interface: Regexp.escape(@interface))})+/
      end
    end
  end
end
