# frozen_string_literal: true

module Syskit
  # `syskit doc`, a command of `syskit` (see syskit/cli.rb): the app's models
  # and plans as a static HTML site (see Doc).
  class CLI < Thor
    desc 'doc', "write the app's models and plans as a static HTML site"
    long_desc <<~TEXT
      Writes an index of every device model, bus model, data service, task
      library, task model and profile of the app (and of the bundles it
      uses), a page for each, and each profile's connection plan on the
      robot, drawn with graphviz when it is installed. The site works
      offline, from file://; the same app gives the same files.

      --output defaults to doc/site in the app; a directory there is only
      replaced if syskit doc wrote it.

      Example: syskit doc --app ~/dev/awesome_robot --output /tmp/site
    TEXT
    method_option :app, type: :string, desc: 'the app directory'
    method_option :robot, type: :string, default: 'default', desc: 'the robot configuration the plans are made for'
    method_option :output, type: :string, desc: 'where to write the site (default: doc/site in the app)'
    def doc
      # Every task library of the app is documented, not only those its
      # profiles use (as syskit check loads them).
      with_app(load: false) do |app|
        app.load!(robots: [options[:robot]], everything: true)
        app.robot_config(options[:robot])
        output = options[:output] ? File.expand_path(options[:output]) : File.join(app.root, 'doc', 'site')
        result = Doc.build(app, output: output, robot: options[:robot])
        report_site(result)
        note_warnings(app)
      end
    end

    private

    # What syskit doc wrote, and what the site could not show.
    def report_site(result)
      style = Style.for($stderr)
      result.unplanned.each do |profile, errors|
        warn style.warning("#{profile.name} could not be planned (#{errors.first.message}): its page says why")
      end
      warn style.warning('graphviz is not installed: plans are listed, not drawn (install graphviz)') unless result.dot
      puts "wrote #{Naming.count(result.pages, 'page')} to #{result.output}"
      puts "open #{File.join(result.output, 'index.html')}"
    end
  end
end
