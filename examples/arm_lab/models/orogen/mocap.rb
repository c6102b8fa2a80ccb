require 'models/devices/mocap/body'

Syskit.extend_model OroGen.mocap.BodyTask do
  driver_for ArmLab::Devices::Mocap::Body, as: 'body'

  # The motion-capture server knows the body by the device's name.
  def configure
    super
    properties.body = body_dev.name
  end
end
