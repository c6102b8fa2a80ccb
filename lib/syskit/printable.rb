# frozen_string_literal: true

module Syskit
  # Bytes from outside (a log's interface names and lines, command-line
  # arguments) as text people and JSON can take: UTF-8, each byte that is
  # not, and each control character, written \xNN.
  module Printable
    module_function

    def text(bytes)
      text = bytes.dup.force_encoding(Encoding::UTF_8)
      return text if text.valid_encoding? && !text.match?(/[[:cntrl:]]/)

      text.scrub { |bad| bad.unpack('C*').map { |b| format('\\x%02X', b) }.join }
          .gsub(/[[:cntrl:]]/) { |c| format('\\x%02X', c.ord) }
    end

    # Whether +bytes+ are UTF-8 text.
    def utf8?(bytes)
      bytes.dup.force_encoding(Encoding::UTF_8).valid_encoding?
    end
  end
end
