# frozen_string_literal: true

module Syskit
  # Reading the files users write (model files, specs, configuration files,
  # robot configurations): as UTF-8 text, a byte-order mark dropped as Ruby
  # itself drops it, and anything that is not text refused at the line of
  # its first bad byte.
  module UserFile
    BOM = "\xEF\xBB\xBF".b.freeze

    module_function

    # The text of +path+: the editor's unsaved text when +path+ is open in
    # it (see #with_buffers), else the file's.
    def read(path)
      bytes = buffer(path) || File.binread(path)
      bytes = bytes.byteslice(BOM.bytesize..) if bytes.start_with?(BOM)
      text = bytes.force_encoding(Encoding::UTF_8)
      return text if text.valid_encoding?

      raise not_text(path, text)
    rescue SystemCallError => e
      raise FileLoadError.new("cannot read #{File.basename(path)}: #{e.message}",
                              location: Location.new(path, 1), hint: 'make it a readable file')
    end

    # Runs the block with +buffers+ (path => text, as an editor holds the
    # files it has open, saved or not) read instead of the files: `syskit
    # lsp` checks what users are typing through the loading code `syskit
    # check` runs on files. Paths are absolute.
    def with_buffers(buffers)
      before = @buffers
      @buffers = buffers.transform_keys { |path| File.expand_path(path) }
      yield
    ensure
      @buffers = before
    end

    # The text of +path+ in the buffers of #with_buffers, as bytes; nil when
    # it is not open.
    def buffer(path)
      @buffers[File.expand_path(path)]&.b if @buffers
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
