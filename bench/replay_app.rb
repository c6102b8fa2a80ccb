# frozen_string_literal: true

require_relative 'synthetic_app'

module Syskit
  module Bench
    module Replay
      # The app whose plan has the replay's 64 devices (Replay.bus_devices:
      # the same names, filters and directions) on the bus can0, so that
      # `syskit bus replay` can be timed as a whole process, as users run
      # it. The device and task models are the synthetic app's.
      module App
        module_function

        # Writes the app into +dir+ and returns +dir+.
        def write(dir, devices)
          SyntheticApp.write(dir, 1)
          File.write(File.join(dir, 'models', 'profiles', 'base.rb'), profile(devices))
          File.write(File.join(dir, 'config', 'robots', 'default.rb'), robot(devices))
          dir
        end

        # Devices that receive are thermometers (bidirectional), the others
        # sync devices (write-only).
        def profile(devices)
          lines = devices.map do |device|
            can_id = device.attributes['can_id']
            kind = if device.bus_to_client
                     "Devices::Thermometer, as: '#{device.name}'"
                   else
                     "Devices::Sync, as: '#{device.name}', bus_to_client: false"
                   end
            filter = can_id ? format('.can_id(0x%<id>x, 0x%<mask>x)', id: can_id[0], mask: can_id[1]) : ''
            "          device(#{kind})#{filter}.prefer_deployed_tasks('#{device.name}')\n"
          end
          <<~RUBY
            using_task_library 'canbus'
            using_task_library 'bench'

            module Bench
              module Profiles
                profile 'Base' do
                  robot do
                    com_bus(CommonModels::Devices::Bus::CAN, as: 'can0', using: OroGen.canbus.Task).prefer_deployed_tasks('can0')
                    through 'can0' do
            #{lines.join}        end
                  end
                end
              end
            end
          RUBY
        end

        def robot(devices)
          deployments = devices.map do |device|
            task = device.bus_to_client ? 'ThermometerTask' : 'SyncTask'
            "Syskit.conf.use_deployment OroGen.bench.#{task} => '#{device.name}'\n"
          end
          "using_task_library 'bench'\nSyskit.conf.use_deployment OroGen.canbus.Task => 'can0'\n#{deployments.join}"
        end
      end
    end
  end
end
