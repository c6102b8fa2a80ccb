# frozen_string_literal: true

require 'erb'
require 'fileutils'
require 'tmpdir'
require 'syskit/doc/catalog'
require 'syskit/doc/page'
require 'syskit/doc/model_view'
require 'syskit/doc/task_model_view'
require 'syskit/doc/profile_view'
require 'syskit/doc/composition_view'
require 'syskit/doc/guides'

module Syskit
  module Doc
    # Writes the site of a loaded app: an index, a page per entry of the
    # Catalog, a page per guide of syskit (Guides), and the assets (one
    # style sheet, one script). Pages are
    # written into a directory beside the output and moved in place once
    # all are written, so a failure never leaves half a site.
    class Site
      TEMPLATES = File.expand_path('../../../templates/doc', __dir__)
      ASSETS = %w[style.css search.js].freeze
      # What marks a directory as a site this command wrote (and may
      # replace).
      GENERATOR = 'syskit doc'

      # What was written: the site's directory, its pages, and the
      # profiles that could not be planned (with their errors).
      Result = Struct.new(:output, :pages, :unplanned, :dot)

      attr_reader :app, :catalog, :robot, :guides

      # +dot+: the path of Graphviz's dot, or nil (the pages then say how
      # to get it).
      def initialize(app, robot: 'default', dot: nil, guides: Guides.new)
        @app = app
        @robot = robot
        @dot = dot
        @catalog = Catalog.new(app)
        @guides = guides
        @templates = {}
      end

      # The compiled template +name+ (templates/doc/NAME.html.erb).
      def template(name)
        @templates[name] ||= ERB.new(File.read(File.join(TEMPLATES, "#{name}.html.erb")), trim_mode: '-')
      end

      # Writes the site into +output+ (replacing a site written there
      # before); returns a Result.
      def write(output)
        output = File.expand_path(output)
        check_output(output)
        FileUtils.mkdir_p(File.dirname(output))
        staging = Dir.mktmpdir('.syskit-doc-', File.dirname(output))
        begin
          result = write_into(staging, output)
          replace(output, staging)
          result
        ensure
          FileUtils.rm_rf(staging)
        end
      end

      # The HTML of the page of +entry+ (or of the index when nil).
      def page_html(entry, view = entry && view_for(entry))
        page = Page.new(self, entry ? entry.path : 'index.html')
        return page.render('layout', title: app.name, body: page.render('index'), crumb: nil) unless entry

        page.render('layout', title: entry.name, body: page.render(entry.kind.template, entry: entry, view: view),
                              crumb: [entry.kind.title, "index.html##{entry.kind.dir}"])
      end

      # The HTML of the page of +guide+ (a Guides::Guide).
      def guide_html(guide)
        page = Page.new(self, guide.path)
        page.render('layout', title: guide.title, body: page.render('guide', guide: guide),
                              crumb: ['Guides', 'index.html#guides'])
      end

      # What the template of +entry+ reads: its kind's view, or the object.
      def view_for(entry)
        view = entry.kind.view
        view ? Doc.const_get(view).new(catalog, entry.object, robot: robot, dot: @dot) : entry.object
      end

      private

      def write_into(dir, output)
        pages = 0
        unplanned = []
        write_file(dir, 'index.html', page_html(nil))
        catalog.each_entry do |entry|
          view = view_for(entry)
          write_file(dir, entry.path, page_html(entry, view))
          pages += 1
          unplanned << [entry.object, view.error] if view.is_a?(ProfileView) && view.error
        end
        guides.each do |guide|
          write_file(dir, guide.path, guide_html(guide))
          pages += 1
        end
        ASSETS.each { |asset| write_file(dir, "assets/#{asset}", File.read(File.join(TEMPLATES, asset))) }
        Result.new(output, pages + 1, unplanned, @dot)
      end

      def write_file(dir, path, content)
        full = File.join(dir, path)
        FileUtils.mkdir_p(File.dirname(full))
        File.binwrite(full, content)
      end

      # An existing output is replaced only when it is a site written by
      # this command (or an empty directory): --output pointing at the
      # wrong directory must not delete it.
      def check_output(output)
        return unless File.exist?(output)
        return if File.directory?(output) && (Dir.empty?(output) || site?(output))

        what = File.directory?(output) ? 'a directory that is not a site written by syskit doc' : 'a file'
        raise Error.new("cannot write the site into #{output}: it is #{what}",
                        hint: 'give another --output, or remove it first')
      end

      def site?(dir)
        index = File.join(dir, 'index.html')
        File.file?(index) && File.read(index, 4096).include?(%(<meta name="generator" content="#{GENERATOR}))
      end

      def replace(output, staging)
        old = nil
        if File.exist?(output)
          old = "#{staging}.old"
          File.rename(output, old)
        end
        File.rename(staging, output)
        FileUtils.mkdir_p(staging) # removed by #write, as if it were still there
        FileUtils.rm_rf(old) if old
      end
    end
  end
end
