require 'models/devices/roboteq/can_open'

Syskit.extend_model OroGen.roboteq.Task do
  driver_for AwesomeRobot::Devices::Roboteq::CANOpen, as: 'roboteq'

  def configure
    super
    # 'roboteq' in roboteq_dev matches the 'roboteq' name in `driver_for`
    id, mask = roboteq_dev.can_id
    properties.can_id = id
    properties.can_mask = mask
  end
end
