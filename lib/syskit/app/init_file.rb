# frozen_string_literal: true

require 'syskit/source_calls'

module Syskit
  class App
    # What a Rock app's config/init.rb says about how Roby loads it, read
    # with Ruby's parser (the file itself is Roby's, and not run).
    module InitFile
      PATH = File.join('config', 'init.rb')

      module_function

      # Whether every file under models/ is loaded before the tests run
      # (Roby's auto_load_models, true unless config/init.rb sets it to
      # false: the app then loads what its robot configurations and test
      # files require, as common_models does).
      def auto_load_models?(root)
        path = File.join(root, PATH)
        return true unless File.file?(path)

        SourceCalls.assignments(UserFile.read(path), :auto_load_models).last != false
      rescue Syskit::Error
        true # a file that cannot be read is Roby's to report; everything is loaded, and checked
      end
    end
  end
end
