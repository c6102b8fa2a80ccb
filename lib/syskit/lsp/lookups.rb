# frozen_string_literal: true

require 'syskit/lsp/nesting'

module Syskit
  module LSP
    # What the queries look up around the cursor (a Resolver's +app+ and
    # +cursor+): the profiles that apply, their devices and definitions,
    # constants as Ruby finds them from the cursor's line, the statement a
    # chained call is on, the composition being written.
    module Lookups
      # The profile the cursor's method is called on (+Base+ of
      # Base.gps_dev), else the profiles declared in the cursor's file,
      # else all of them.
      def profiles
        receiver = cursor.receiver_constant && profile_of(constant(cursor.receiver_constant))
        return [receiver] if receiver.is_a?(Actions::Profile)

        all = app.profiles.values
        own = all.select { |p| p.declared_at&.path == cursor.path }
        own.empty? ? all : own
      end

      # The device or bus +name+ of the file's profiles' robots.
      def device(name)
        profiles.each do |profile|
          found = profile.robot.find_device(name)
          return found if found
        end
        nil
      end

      # The definition +name+ of the file's profiles.
      def definition(name)
        profiles.each do |profile|
          found = profile.find_definition(name)
          return found if found
        end
        nil
      end

      # The constant +path+ as Ruby looks it up from the cursor's line:
      # in each module around it, innermost first, then at the top level.
      # When the buffer does not parse, the saved file's modules are used.
      def constant(path)
        return lookup(Object, path.delete_prefix('::')) if path.start_with?('::')

        scopes.each do |scope|
          base = lookup(Object, scope)
          found = base && lookup(base, path)
          return found if found
        end
        lookup(Object, path)
      end

      # The modules around the cursor's line, innermost first.
      def scopes
        @scopes ||= begin
          found = Nesting.at(cursor.text, cursor.lineno)
          found = Nesting.at(File.read(cursor.path), cursor.lineno) if found.empty? && File.file?(cursor.path.to_s)
          found
        end
      end

      # The device or definition whose statement is the closest one above
      # the cursor's line in its file (what a chained +with_conf+ is on).
      def statement_above
        candidates = profiles.flat_map { |p| p.robot.each_master_device.to_a + p.definitions.values }
        candidates.select { |c| c.declared_at&.path == cursor.path && c.declared_at.lineno <= cursor.lineno }
                  .max_by { |c| c.declared_at.lineno }
      end

      # The composition model whose class body holds the cursor.
      def composition
        scopes.lazy.map { |s| lookup(Object, s) }.find { |m| m.is_a?(Class) && m < Composition }
      end

      # The model whose configurations a device or definition chooses
      # among: a device's driver, a definition's task model or composition
      # (see ConfSections).
      def conf_model(holder)
        if holder.is_a?(Robot::MasterDeviceInstance)
          holder.driver_model.component_model if holder.driver_resolved?
        elsif holder
          holder.component_model
        end
      end

      private

      def lookup(base, path)
        path.split('::').reduce(base) do |mod, name|
          return nil unless mod.is_a?(Module) && name.match?(/\A[A-Z]\w*\z/) && mod.const_defined?(name, false)
          return nil if mod.autoload?(name)

          mod.const_get(name, false)
        end
      rescue NameError # an autoload that failed
        nil
      end

      # A profile's module stands for its profile.
      def profile_of(object)
        profile_module = object.is_a?(Module) && object.singleton_class.include?(Actions::Profile::ModuleMethods)
        profile_module ? object.syskit_profile : object
      end
    end
  end
end
