Syskit.extend_model OroGen.simple_can.Task do
  provides CommonModels::Devices::Bus::CAN::BusSrv, as: 'canbus'
end
