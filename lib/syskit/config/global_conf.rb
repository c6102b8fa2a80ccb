# frozen_string_literal: true

module Syskit
  module Config
    # +Syskit.conf+ outside robot configuration files: model files ask it
    # questions about the running system (+Syskit.conf.sim?+), which have
    # the answers of a plan of the real robot. Deployments are declared in
    # robot configuration files only.
    class GlobalConf
      # Questions and their answers here.
      ANSWERS = { sim?: false, backward_compatible_naming?: false, transformer_enabled?: false,
                  only_load_models?: true, opportunistic_recovery_from_quarantine?: false,
                  auto_restart_deployments_with_quarantines?: false }.freeze

      ANSWERS.each { |question, answer| define_method(question) { answer } }

      # The statements of robot configuration files, refused here.
      %i[use_deployment use_deployments_from use_unmanaged_task use_ruby_tasks].each do |statement|
        define_method(statement) do |*_args, **_options|
          raise Error.new("Syskit.conf.#{statement} is only available in robot configuration files",
                          location: Location.of_caller,
                          hint: 'declare deployments in config/robots/<robot>.rb')
        end
      end

      def to_s
        'Syskit.conf'
      end
    end
  end
end
