# frozen_string_literal: true

require 'fileutils'

module Syskit
  module Bench
    # Writes a real app with +devices+ devices spread over CAN buses of 32
    # devices each, for the benchmark:
    # - even buses use the bundled demultiplexing canbus::Task (configure +
    #   stub), odd buses a driver that does not demultiplex (BusSrv);
    # - four device models and drivers: bidirectional (two of them), read-only
    #   and write-only;
    # - every device told apart from the others of its model by
    #   prefer_deployed_tasks and given its own configuration sections;
    # - a robot configuration that deploys everything.
    #
    # With +compositions+, every device is also used by a definition of
    # the profile, one per device: a composition of its kind whose first
    # child is the device (by its device model, whose port the driver
    # provides, or by its driver's task model) and whose second child
    # processes its data (a task of its own, told apart by
    # prefer_deployed_tasks), plus a clock child all compositions share
    # (equal tasks: merged into one).
    class SyntheticApp
      PER_BUS = 32
      KINDS = [
        { model: 'Thermometer', task: 'ThermometerTask', options: '' },
        { model: 'Pressure', task: 'PressureTask', options: ', client_to_bus: false' },
        { model: 'Motor', task: 'MotorTask', options: '' },
        { model: 'Sync', task: 'SyncTask', options: ', bus_to_client: false' }
      ].freeze

      # What each kind's composition holds: the device child (by device
      # model or by driver task model), the processing child and the ports
      # connected, data from the device or commands to it.
      COMPOSITIONS = {
        'Thermometer' => { device: 'Devices::Thermometer', task: 'FilterTask', from: 'sensor.temperature',
                           to: 'process.value' },
        'Pressure' => { device: 'OroGen.bench.PressureTask', task: 'FilterTask', from: 'sensor.pressure',
                        to: 'process.value' },
        'Motor' => { device: 'Devices::Motor', task: 'ControllerTask', from: 'process.command',
                     to: 'sensor.command' },
        'Sync' => { device: 'OroGen.bench.SyncTask', task: 'ControllerTask', from: 'process.command',
                    to: 'sensor.command' }
      }.freeze

      # With compositions, thermometers and motors declare the port their
      # composition connects (a child of a device model reaches its
      # driver's port through the device's).
      DEVICE_PORTS = { 'Thermometer' => "output_port 'temperature', '/double'",
                       'Motor' => "input_port 'command', '/double'" }.freeze

      def self.write(dir, devices, compositions: false)
        new(dir, devices, compositions: compositions).write
      end

      def initialize(dir, devices, compositions: false)
        @dir = dir
        @devices = devices
        @compositions = compositions
        @buses = (devices + PER_BUS - 1) / PER_BUS
      end

      def write
        file('config/syskit.yml', "name: Bench\nacronyms: [CAN]\n")
        file('models/devices/sensors.rb', devices_file)
        file('models/orogen/bench.orogen', spec_file)
        file('models/orogen/bench.rb', extension_file)
        file('config/orogen/bench::MotorTask.yml', conf_file('gain'))
        file('config/orogen/bench::ThermometerTask.yml', conf_file('threshold'))
        file('config/orogen/canbus::Task.yml', "--- name:default\ndeviceType: SOCKET\n")
        file('models/profiles/base.rb', profile_file)
        file('config/robots/default.rb', robot_file)
        file('models/compositions/processing.rb', compositions_file) if @compositions
        @dir
      end

      private

      def file(path, content)
        full = File.join(@dir, path)
        FileUtils.mkdir_p(File.dirname(full))
        File.write(full, content)
      end

      def devices_file
        models = KINDS.map do |k|
          port = @compositions && DEVICE_PORTS[k[:model]]
          port ? "    device_type '#{k[:model]}' do\n      #{port}\n    end" : "    device_type '#{k[:model]}'"
        end
        "module Bench\n  module Devices\n#{models.join("\n")}\n  end\nend\n"
      end

      def compositions_file
        models = KINDS.map do |k|
          c = COMPOSITIONS.fetch(k[:model])
          from_child, from_port = c[:from].split('.')
          to_child, to_port = c[:to].split('.')
          <<~RUBY.gsub(/^/, '    ')
            class #{k[:model]}Processing < Syskit::Composition
              add #{c[:device]}, as: 'sensor'
              add OroGen.bench.#{c[:task]}, as: 'process'
              add OroGen.bench.ClockTask, as: 'clock'
              #{from_child}_child.#{from_port}_port.connect_to #{to_child}_child.#{to_port}_port
              clock_child.tick_port.connect_to process_child.tick_port
            end
          RUBY
        end
        "require 'models/devices/sensors'\nusing_task_library 'bench'\n\nmodule Bench\n  module Compositions\n" \
          "#{models.join("\n")}  end\nend\n"
      end

      def spec_file
        <<~RUBY
          name 'bench'
          import_types_from 'canbus'

          task_context 'ThermometerTask' do
            property 'threshold', 'double', 1.0
            input_port('can_in', '/canbus/Message').needs_reliable_connection
            output_port 'can_out', '/canbus/Message'
            output_port 'temperature', '/double'
          end

          task_context 'PressureTask' do
            input_port 'can_in', '/canbus/Message'
            output_port 'pressure', '/double'
          end

          task_context 'MotorTask' do
            property 'can_id', 'int'
            property 'can_mask', 'int'
            property 'gain', 'double', 1.0
            input_port('can_in', '/canbus/Message').needs_reliable_connection
            output_port 'can_out', '/canbus/Message'
          #{"  input_port 'command', '/double'" if @compositions}
          end

          task_context 'SyncTask' do
            output_port 'can_out', '/canbus/Message'
          #{"  input_port 'command', '/double'" if @compositions}
          end
          #{processing_tasks if @compositions}

          # A bus driver that does not demultiplex.
          task_context 'BusTask' do
            input_port('can_in', '/canbus/Message').multiplexes.needs_reliable_connection
            output_port 'can_out', '/canbus/Message'
          end
        RUBY
      end

      def processing_tasks
        <<~RUBY
          task_context 'FilterTask' do
            input_port 'value', '/double'
            input_port 'tick', '/double'
            output_port 'filtered', '/double'
          end

          task_context 'ControllerTask' do
            input_port 'tick', '/double'
            output_port 'command', '/double'
          end

          task_context 'ClockTask' do
            output_port 'tick', '/double'
          end
        RUBY
      end

      def extension_file
        drivers = KINDS.map do |k|
          "Syskit.extend_model OroGen.bench.#{k[:task]} do\n  driver_for Bench::Devices::#{k[:model]}, as: 'dev'\nend\n"
        end
        <<~RUBY
          require 'models/devices/sensors'

          #{drivers.join("\n")}
          Syskit.extend_model OroGen.bench.MotorTask do
            def configure
              super
              properties.can_id, properties.can_mask = dev_dev.can_id
            end
          end

          Syskit.extend_model OroGen.bench.BusTask do
            provides CommonModels::Devices::Bus::CAN::BusSrv, as: 'bus'
          end
        RUBY
      end

      # A default section and eight more (gain for motors, threshold for
      # thermometers; the other property is unknown to the other model, so
      # each file only sets its own).
      def conf_file(property)
        sections = (0...8).map { |s| "--- name:s#{s}\n#{property}: #{s + 1}.5\n" }
        "--- name:default\n#{property}: 1.0\n#{sections.join}"
      end

      def profile_file
        out = +"using_task_library 'canbus'\nusing_task_library 'bench'\n"
        out << "require 'models/compositions/processing'\n" if @compositions
        out << "\nmodule Bench\n  module Profiles\n    profile 'Base' do\n      robot do\n"
        @buses.times do |b|
          driver = b.even? ? 'OroGen.canbus.Task' : 'OroGen.bench.BusTask'
          out << "        com_bus(CommonModels::Devices::Bus::CAN, as: 'can#{b}', using: #{driver})" \
                 ".prefer_deployed_tasks('can#{b}')\n"
          out << "        through 'can#{b}' do\n"
          ((b * PER_BUS)...[(b + 1) * PER_BUS, @devices].min).each { |i| out << device_line(i) }
          out << "        end\n"
        end
        out << "      end\n"
        @devices.times { |i| out << definition_line(i) } if @compositions
        out << "    end\n  end\nend\n"
      end

      def definition_line(index)
        kind = KINDS[index % KINDS.size]
        process = "OroGen.bench.#{COMPOSITIONS.fetch(kind[:model])[:task]}.prefer_deployed_tasks('process#{index}')"
        "      define 'process#{index}', Compositions::#{kind[:model]}Processing\n        " \
          ".use('sensor' => dev#{index}_dev, 'process' => #{process})\n"
      end

      def device_line(index)
        kind = KINDS[index % KINDS.size]
        conf = %w[Motor Thermometer].include?(kind[:model]) ? ".with_conf('default', 's#{index % 8}')" : ''
        "          device(Devices::#{kind[:model]}, as: 'dev#{index}'#{kind[:options]})" \
          ".can_id(0x#{(0x100 + (index % PER_BUS)).to_s(16)}, 0x7ff)" \
          ".prefer_deployed_tasks('dev#{index}')#{conf}.period(0.01)\n"
      end

      def processing_deployments(out)
        out << "Syskit.conf.use_deployment OroGen.bench.ClockTask => 'clock'\n"
        @devices.times do |i|
          task = COMPOSITIONS.fetch(KINDS[i % KINDS.size][:model])[:task]
          out << "Syskit.conf.use_deployment OroGen.bench.#{task} => 'process#{i}'\n"
        end
      end

      def robot_file
        out = +"using_task_library 'bench'\n"
        @buses.times do |b|
          task = b.even? ? 'OroGen.canbus.Task' : 'OroGen.bench.BusTask'
          out << "Syskit.conf.use_deployment #{task} => 'can#{b}'\n"
        end
        @devices.times do |i|
          out << "Syskit.conf.use_deployment OroGen.bench.#{KINDS[i % KINDS.size][:task]} => 'dev#{i}'\n"
        end
        processing_deployments(out) if @compositions
        out
      end
    end
  end
end
