# frozen_string_literal: true

require 'syskit/refused_call'

module Syskit
  # Runs code users wrote (model files, .orogen specs, configure methods) and
  # turns whatever it raises into a Syskit::Error that says what went wrong,
  # at which line of the user's file, and how to fix it.
  #
  # Objects that users call methods on (namespaces, DSL contexts, devices,
  # properties) explain a missing method through +explain_missing(name)+,
  # which returns +[message, hint]+ (or nil, to leave it to Ruby's message).
  module UserCode
    # instance_eval of a string, made at the top level: the file's constants
    # resolve as in a file Ruby loads (+Robot+ is ::Robot), not from the
    # gem's modules an instance_eval written here would add to its scope.
    TOPLEVEL_INSTANCE_EVAL =
      TOPLEVEL_BINDING.eval('->(receiver, source, path) { receiver.instance_eval(source, path, 1) }')

    # A file required through its bundle's name, as Rock finds them:
    # 'NAME/models/x' (the bundle's directory name, the path in it).
    BUNDLE_FILE = %r{\A([^/]+)/(models/.+)\z}

    module_function

    # Evaluates the file at +path+ with +receiver+ as self; what it raises
    # becomes an +error_class+ error at the file's line.
    def evaluate(path, receiver, root: nil, error_class: FileLoadError)
      source = UserFile.read(path)
      guard(path: path, root: root, error_class: error_class) do
        TOPLEVEL_INSTANCE_EVAL.call(receiver, source, path)
      end
    end

    # Runs user code. Whatever it raises, exits and non-StandardError
    # exceptions included (+exit+, +abort+, an endless recursion), becomes a
    # located Syskit error (see #translate); Syskit errors pass as they are.
    # Only signals (Ctrl-C) go through untouched.
    def guard(path: nil, root: nil, error_class: FileLoadError, context: nil)
      yield
    rescue Exception => e # rubocop:disable Lint/RescueException -- user code may raise anything
      raise if e.is_a?(SignalException) || Syskit::Error === e # rubocop:disable Style/CaseEquality -- see Error.===

      raise translate(e, path: path, root: root, error_class: error_class, context: context)
    end

    # A Syskit::Error for +exception+. +path+ is the file being evaluated:
    # the location is then its line in that file.
    def translate(exception, path: nil, root: nil, error_class: FileLoadError, context: nil)
      case exception
      when Syskit::Error
        exception.location ? exception : exception.at(location_of(exception, path))
      when SyntaxError
        syntax_error(exception, path)
      when NameError
        name_error(exception, path, root, error_class, context)
      else
        message, hint = describe(exception)
        error_class.new(context ? "#{context}: #{message}" : message,
                        location: location_of(exception, path, root), hint: hint)
      end.tap { |error| error.set_backtrace(exception.backtrace || []) if error.backtrace.nil? }
    end

    # The innermost line of the user's code: in the file being evaluated
    # (+path+) or in the app and its bundles (a file required from +path+ is
    # reported at its own line), else the first frame outside the gem.
    # What users read for an exception their code raised, and a hint.
    def describe(exception)
      case exception
      when SystemExit
        what = exception.message == 'exit' ? "exit (status #{exception.status})" : "abort: #{exception.message}"
        ["the code calls #{what}", 'syskit evaluates this file: do not exit from it, raise an error instead']
      when SystemStackError
        ['stack level too deep (an endless recursion?)', 'find the method that calls itself without end']
      when NoMemoryError
        ["out of memory (#{first_line(exception.message)})", 'look for a loop that builds ever bigger values']
      when LoadError
        ["#{exception.class}: #{first_line(exception.message)}",
         renamed_app_hint(exception.path) || missing_file_hint(exception.path) ||
           'fix the code at this line (run with --trace for the backtrace)']
      else
        RefusedCall.of(exception)&.describe ||
          ["#{exception.class}: #{first_line(exception.message)}",
           'fix the code at this line (run with --trace for the backtrace)']
      end
    end

    # Rock finds 'NAME/models/x' by the name of a bundle's directory: an
    # app copied or cloned under another name no longer finds its own
    # files required that way. The hint for such a require, nil otherwise.
    def renamed_app_hint(required)
      name, relative = required.to_s.match(BUNDLE_FILE)&.captures
      root = Syskit.app&.root
      return unless name && root && File.basename(root) != name &&
                    File.file?(File.join(root, "#{relative.delete_suffix('.rb')}.rb"))

      "'#{name}/#{relative}' is this app's own #{relative}, found through the name of the app's " \
        "directory as Rock does, but the directory is named '#{File.basename(root)}': rename it to " \
        "'#{name}', or require '#{relative}'"
    end

    # A file of one of the app's bundles ('NAME/models/x') that does not
    # exist: what its directory has that is closest. nil for another file.
    def missing_file_hint(required)
      name, relative = required.to_s.match(BUNDLE_FILE)&.captures
      bundle = name && Syskit.app&.bundles&.find { |b| File.basename(b.root) == name }
      return unless bundle

      missing = "the bundle #{name} (#{bundle.root}) has no"
      dir = File.dirname(relative)
      if File.directory?(File.join(bundle.root, dir))
        file = "#{relative.delete_suffix('.rb')}.rb"
        "#{missing} #{file}#{closest(File.join(bundle.root, file), '.rb')}"
      else
        "#{missing} directory #{dir}#{closest(File.join(bundle.root, dir), nil)}"
      end
    end

    # " (did you mean 'x'?)" for the names beside +path+ closest to its own:
    # files ending in +suffix+, or directories when it is nil; '' for none.
    def closest(path, suffix)
      dir = File.dirname(path)
      names = File.directory?(dir) ? Dir.children(dir) : []
      names = if suffix
                names.grep(/#{Regexp.escape(suffix)}\z/).map { |n| n.delete_suffix(suffix) }
              else
                names.select { |n| File.directory?(File.join(dir, n)) }
              end
      Naming.did_you_mean(File.basename(path, suffix.to_s), names)
    end

    def location_of(exception, path, root = nil)
      prefix = root && "#{File.expand_path(root)}/"
      found = (exception.backtrace_locations || []).find do |loc|
        file = loc.absolute_path || loc.path
        file == path || (app_file?(file, prefix) && !file.start_with?(Location::GEM_LIB))
      end
      Location.from(found) || Location.of_exception(exception)
    end

    # Whether +file+ is under +prefix+ (the root given) or a file of the
    # active app or its bundles (of the gem's own, its models/ only).
    def app_file?(file, prefix)
      (prefix && file.start_with?(prefix)) || Syskit.app&.environment_file?(file)
    end

    def syntax_error(exception, path)
      lines = exception.message.lines
      header = lines.find { |l| l =~ /\A(.+?):(\d+): (.*)/ }
      if header
        file, line, text = header.match(/\A(.+?):(\d+): (.*)/).captures
        location = Location.new(File.expand_path(file), Integer(line))
      else
        text = first_line(exception.message)
        location = path && Location.new(path, 0)
      end
      FileLoadError.new("syntax error: #{text.strip.delete_prefix('syntax error, ')}",
                        location: location, hint: 'fix the Ruby syntax at this line')
    end

    def name_error(exception, path, root, error_class, context)
      message, hint = explain(exception)
      message = "#{context}: #{message}" if context
      location = location_of(exception, path, root)
      error_class.new(message, location: location, hint: require_hint(exception, location) || hint)
    end

    # For a constant of the app's models that its file was not required
    # for: the require to add, which a spelling suggestion would hide. When
    # that file failed to load, that error is the one to fix; when it is
    # loaded, requiring it again changes nothing, and the spelling
    # suggestion (MC200 for Mc200) is the hint.
    def require_hint(exception, location)
      return unless exception.instance_of?(NameError) && exception.name && location&.lineno.to_i.positive?

      app = Syskit.app
      constant = constant_at(location, exception.name.to_s)
      path = constant && app&.file_defining(constant)
      return unless path && File.expand_path("#{path}.rb", app.root) != location.path

      defining_file_hint(app, constant, path)
    end

    def defining_file_hint(app, constant, path)
      if (failure = app.load_failure(path))
        "#{constant} is defined in #{path}.rb, which failed to load (#{failure.to_s(app.root)}): fix that error first"
      elsif !app.loaded_file?(path)
        "#{constant} is defined in #{path}.rb, which this file does not require: add require '#{path}' at its top"
      end
    end

    # The constant path written at +location+ that names +name+
    # (Services::Pose for Services).
    def constant_at(location, name)
      line = File.foreach(location.path).drop(location.lineno - 1).first.to_s
      line[/(?:\b[A-Z]\w*::)*\b#{Regexp.escape(name)}\b(?:::[A-Z]\w*)*/]
    rescue SystemCallError, IOError
      nil
    end

    # The receiver's own explanation of a missing method or constant, or
    # Ruby's message with spelling suggestions.
    def explain(exception)
      receiver = receiver_of(exception)
      name = exception.name
      explained = receiver.explain_missing(name.to_s) if name && receiver.respond_to?(:explain_missing)
      return explained if explained
      return not_a_task_model(receiver) if made_by_a_class_statement?(receiver)

      message = original_message(exception).sub(/ for #<[^>]*>\z/, '')
      return [message, Compat::OldCommonModels.constant_hint] if old_common_models?(exception)

      [message, suggestion(exception, receiver) || missing_hint(exception)]
    end

    # +class OroGen::Lib::Name ... end+ for a task the library does not
    # have makes a plain class in its namespace, which has none of a task
    # model's statements.
    def made_by_a_class_statement?(receiver)
      receiver.is_a?(Class) && receiver.name.to_s.start_with?('OroGen::') && !(receiver < Syskit::TaskContext)
    end

    def not_a_task_model(klass)
      namespace = Object.const_get(klass.name.split('::')[0..-2].join('::'))
      tasks = namespace.respond_to?(:names) ? namespace.names.join(', ') : 'none'
      ["#{klass.name} is not a task model: the class statement made a new class, as #{namespace} has no " \
       "task model #{klass.name.split('::').last}",
       "its task models are #{tasks}; check the name against the library's .orogen file"]
    end

    # Ruby's own message, without the code excerpt error_highlight adds.
    def original_message(exception)
      text = exception.respond_to?(:original_message) ? exception.original_message : exception.message
      first_line(text)
    end

    def suggestion(exception, receiver)
      return super_hint if exception.message.start_with?('super')

      spelling_suggestion(exception, receiver)
    rescue StandardError
      # did_you_mean cannot always compute corrections (e.g. for super)
      nil
    end

    def super_hint
      'super only works inside a method that overrides another (configure does; stub blocks do not)'
    end

    def spelling_suggestion(exception, receiver)
      candidates =
        if !exception.is_a?(NoMethodError) && receiver.is_a?(Module)
          receiver.constants.map { |c| receiver == Object ? c.to_s : "#{receiver.name}::#{c}" }
        elsif exception.respond_to?(:corrections)
          return corrections_hint(exception.corrections)
        end
      return unless candidates

      prefix = receiver == Object ? '' : "#{receiver.name}::"
      corrections_hint(Naming.suggest("#{prefix}#{exception.name}", candidates))
    end

    def corrections_hint(corrections)
      "did you mean #{corrections.map { |c| "'#{c}'" }.join(' or ')}?" unless corrections.nil? || corrections.empty?
    end

    def old_common_models?(exception)
      exception.instance_of?(NameError) && exception.name == :Rock && !Object.const_defined?(:Rock)
    end

    def missing_hint(exception)
      if exception.is_a?(NoMethodError)
        'check the spelling and the object the method is called on'
      else
        "check the spelling, and that the file defining #{exception.name} is required or loaded"
      end
    end

    def receiver_of(exception)
      exception.receiver
    rescue ArgumentError
      nil
    end

    def first_line(text)
      text.to_s.lines.first.to_s.strip
    end
  end
end
