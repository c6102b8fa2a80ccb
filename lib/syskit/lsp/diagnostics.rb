# frozen_string_literal: true

module Syskit
  module LSP
    # The problems of `syskit check` as the editor's diagnostics, by file:
    # the line of each problem's location, its message, and its hint as
    # related information (editors show it under the message; for those
    # that do not, the server puts it in the message, see Server).
    module Diagnostics
      Severity = LanguageServer::Protocol::Constant::DiagnosticSeverity

      module_function

      # { path => [diagnostic Hash, ...] } of +problems+. A problem without
      # a location (the app as a whole) goes on +fallback_path+, at its
      # first line. +text_of+ gives the text of a file (the editor's buffer
      # or the file's), whose lines the ranges cover.
      def by_file(problems, fallback_path:, text_of:)
        lines = Hash.new { |h, path| h[path] = text_of.call(path).to_s.lines }
        problems.each_with_object(Hash.new { |h, k| h[k] = [] }) do |problem, result|
          path = problem.location&.path || fallback_path
          next unless path

          result[path] << diagnostic(problem, path, lines[path])
        end
      end

      def diagnostic(problem, path, lines)
        range = line_range(lines, problem.location&.lineno.to_i - 1)
        result = { range: range, severity: severity(problem), source: 'syskit',
                   code: problem.class.name.split('::').last, message: problem.message }
        if problem.hint
          result[:relatedInformation] = [{ location: { uri: URI.of(path), range: range },
                                           message: "hint: #{problem.hint}" }]
        end
        result
      end

      # +diagnostic+ with its hint also under its message, for clients that
      # do not show related information.
      def with_hint_in_message(diagnostic)
        related = diagnostic[:relatedInformation]
        return diagnostic unless related

        diagnostic.merge(message: [diagnostic[:message], *related.map { |r| r[:message] }].join("\n"))
      end

      def severity(problem)
        problem.is_a?(Syskit::Warning) ? Severity::WARNING : Severity::ERROR
      end

      # The written part of line +index+ (0-based; the first line when there
      # is no such line), as an LSP range.
      def line_range(lines, index)
        index = 0 unless index.between?(0, lines.size - 1)
        text = lines[index].to_s.chomp
        first = text.index(/\S/) || 0
        { start: { line: index, character: utf16_size(text[0, first]) },
          end: { line: index, character: utf16_size(text) } }
      end

      # LSP counts characters in UTF-16 code units.
      def utf16_size(text)
        text.encode(Encoding::UTF_16LE).bytesize / 2
      rescue EncodingError
        text.size
      end
    end
  end
end
