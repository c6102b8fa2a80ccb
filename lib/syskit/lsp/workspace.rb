# frozen_string_literal: true

module Syskit
  module LSP
    # The documents the editor has open and the app session of each (the
    # app containing the file, found as `syskit` commands find it), and the
    # diagnostics published, so that those fixed are cleared.
    class Workspace
      def initialize(log: $stderr)
        @log = log
        @sessions = {}
        @texts = {}
        @published = Hash.new { |h, session| h[session] = {} }
      end

      # The text the editor has for +path+; nil when it is not open.
      def text(path)
        @texts[path]
      end

      # The session of the app containing +path+, made on first use; for a
      # file of a bundle (common_models), the session of an app that uses
      # that bundle, unless the bundle has a session of its own; nil
      # outside any app.
      def session_for(path)
        root = App.find_root(File.dirname(path)) or return
        @sessions[root] || @sessions.values.find { |session| session.roots.include?(root) } ||
          (@sessions[root] = Session.new(root, log: @log))
      end

      # The editor opened or changed +path+ to +text+: yields the
      # diagnostics to publish, [path, [diagnostic, ...]] each.
      def update(path, text, &)
        @texts[path] = text
        session = session_for(path) or return
        checked = session.update(path, text)
        publish_diagnostics(session, path, all: checked, &)
      end

      # The editor closed +path+.
      def close(path, &)
        @texts.delete(path)
        session = session_for(path) or return
        checked = session.close(path)
        publish_diagnostics(session, path, all: checked, &)
      end

      private

      # The diagnostics of every file with problems and of +path+, and an
      # empty list for files whose problems are gone. Unless the app was
      # checked again (+all+), only +path+'s.
      def publish_diagnostics(session, path, all:)
        text_of = ->(file) { @texts[file] || read(file) }
        current = Diagnostics.by_file(session.problems, fallback_path: path, text_of: text_of)
        published = @published[session]
        files = all ? (published.keys | current.keys | [path]) : [path]
        files.each do |file|
          diagnostics = current.fetch(file, [])
          next if file != path && published[file] == diagnostics

          diagnostics.empty? ? published.delete(file) : published[file] = diagnostics
          yield file, diagnostics
        end
      end

      def read(file)
        File.read(file, encoding: 'UTF-8')
      rescue SystemCallError, IOError
        ''
      end
    end
  end
end
