# frozen_string_literal: true

module Syskit
  module Config
    # The machines a robot's deployments run on, as its configuration
    # declares them: older Syskit's +process_server 'front', 'front.local'+
    # (also +connect_to_orocos_process_server+) and today's
    # +register_process_server 'front', client, log_dir+. A process server
    # is data, a name and a host: nothing connects anywhere.
    #
    # Deployments name theirs with +on:+ (+use_deployment 'cameras', on:
    # 'front'+); the plan says where each runs. Every robot has Syskit's
    # own three: 'localhost' (the default of use_deployment), 'ruby_tasks'
    # and 'unmanaged_tasks' (the defaults of use_ruby_tasks and
    # use_unmanaged_task).
    module ProcessServers
      # A declared process server; +declared_at+ is nil for the built-in ones.
      ProcessServer = Struct.new(:name, :host, :log_dir, :declared_at) do
        def to_s
          host == name ? name : "#{name} (#{host})"
        end
      end

      BUILTIN = %w[localhost ruby_tasks unmanaged_tasks].to_h do |name|
        [name, ProcessServer.new(name, 'localhost', nil, nil).freeze]
      end.freeze

      # Older Syskit's statement: +name+ runs deployments on +host+.
      def process_server(name, host, log_dir: nil, **_runtime_options)
        declare_process_server(name, host, log_dir, Location.of_caller)
      end

      def connect_to_orocos_process_server(name, host, log_dir: nil, **_runtime_options)
        declare_process_server(name, host, log_dir, Location.of_caller)
      end

      # Today's statement: +client+ (a connection to the process server,
      # not modelled here) is known as +name+; +host_id+ names its machine.
      def register_process_server(name, _client = nil, log_dir = nil, host_id: nil)
        declare_process_server(name, host_id || name, log_dir, Location.of_caller)
      end

      def remove_process_server(name)
        own_process_servers.delete(name.to_s)
        Compat::Ignored.instance
      end

      # Process servers by name, the built-in ones first.
      def process_servers
        BUILTIN.merge(own_process_servers)
      end

      def process_server_named(name)
        process_servers[name.to_s]
      end

      private

      def own_process_servers
        @own_process_servers ||= {}
      end

      def declare_process_server(name, host, log_dir, location)
        name = name.to_s
        if (existing = process_servers[name])
          where = existing.declared_at ? " at #{existing.declared_at}" : ' (it is one of Syskit\'s own)'
          raise DeclarationError.new("there is already a process server called '#{name}'#{where}",
                                     location: location, hint: 'give this one another name')
        end

        own_process_servers[name] = ProcessServer.new(name, host.to_s, log_dir&.to_s, location).freeze
        Compat::Ignored.instance
      end

      # +on:+ of a deployment statement must name a declared process server.
      def check_process_server(name, location)
        return if process_servers.key?(name.to_s)

        raise DeploymentError.new(
          "no process server called '#{name}' (declared: #{process_servers.keys.join(', ')})",
          location: location,
          hint: "declare it before the deployments that run on it: Syskit.conf.process_server '#{name}', 'hostname'"
        )
      end
    end
  end
end
