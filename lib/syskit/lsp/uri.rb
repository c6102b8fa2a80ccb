# frozen_string_literal: true

require 'uri'

module Syskit
  module LSP
    # file:// URIs, as editors name documents, to paths and back.
    module URI
      PARSER = ::URI::RFC2396_Parser.new

      module_function

      # The path of a file:// URI; nil for any other scheme (an unsaved
      # editor buffer, a remote file).
      def path(uri)
        parsed = ::URI.parse(uri.to_s)
        File.expand_path(PARSER.unescape(parsed.path)) if parsed.scheme == 'file' && parsed.path
      rescue ::URI::InvalidURIError
        nil
      end

      def of(path)
        "file://#{PARSER.escape(File.expand_path(path))}"
      end
    end
  end
end
