# frozen_string_literal: true

module Syskit
  module Types
    # Type-name helpers of oroGen, available wherever types are written
    # (.orogen files, data service and device blocks, model files).
    module TypeNames
      # oroGen's read-only pointer to +type+: +output_port 'frame',
      # ro_ptr('/base/samples/frame/Frame')+. Components exchange the
      # pointed-to data; the port's type is the pointer's.
      def ro_ptr(type)
        "#{Registry::RO_PTR}<#{Registry.normalize(type.to_s)}>"
      end
    end
  end
end
