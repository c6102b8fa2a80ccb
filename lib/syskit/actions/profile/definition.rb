# frozen_string_literal: true

module Syskit
  module Actions
    class Profile
      # A profile's definition (+define 'arm_control', Cmp.use(...)+):
      # requirements named as written ('arm_control'), with the profile
      # that defines them and their documentation; the action is
      # +Base.arm_control_def+. Statements on it give definitions too.
      class Definition < InstanceRequirements
        protected

        def action_name
          "#{profile}.#{name}_def"
        end
      end
    end
  end
end
