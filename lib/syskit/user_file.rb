# frozen_string_literal: true

module Syskit
  # Reading the files users write (model files, specs, configuration files,
  # robot configurations): as UTF-8 text, a byte-order mark dropped as Ruby
  # itself drops it, and anything that is not text refused at the line of
  # its first bad byte.
  module UserFile
    BOM = "\xEF\xBB\xBF".b.freeze

    module_function

    # The text of +path+.
    def read(path)
      bytes = File.binread(path)
      bytes = bytes.byteslice(BOM.bytesize..) if bytes.start_with?(BOM)
      text = bytes.force_encoding(Encoding::UTF_8)
      return text if text.valid_encoding?

      raise not_text(path, text)
    rescue SystemCallError => e
      raise FileLoadError.new("cannot read #{File.basename(path)}: #{e.message}",
                              location: Location.new(path, 1), hint: 'make it a readable file')
    end

    # Its lines.
    def lines(path)
      read(path).lines
    end

    def not_text(path, text)
      good = text.each_char.take_while(&:valid_encoding?).join
      FileLoadError.new(
        "this file is not UTF-8 text (a byte that is not UTF-8 at line #{good.count("\n") + 1})",
        location: Location.new(path, good.count("\n") + 1),
        hint: 'save it as UTF-8 (e.g. iconv -f latin1 -t utf-8); configuration and model files are text'
      )
    end
  end
end
