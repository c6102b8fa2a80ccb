require 'models/profiles/bench'

module ArmLab
  module Profiles
    describe Bench do
      it { is_self_contained }
      it { can_instanciate }
      it { can_deploy }
      it { can_configure }
    end
  end
end
