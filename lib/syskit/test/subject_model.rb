# frozen_string_literal: true

module Syskit
  module Test
    # The model a test is about, as Syskit's specs name it: the component
    # model of the enclosing +describe+, unless +use_syskit_model+ chose
    # another (an abstract model's concrete one, a specialization).
    #
    #   describe OroGen.joint_tools.Task do
    #     use_syskit_model OroGen.joint_tools.Task.with_conf('default', 'fast')
    #     it { is_configurable }
    #     it 'reads its model' do
    #       task = syskit_stub_deploy_and_configure(subject_syskit_model)
    #     end
    #   end
    module SubjectModel
      # Class methods of the describe blocks.
      module ClassMethods
        def use_syskit_model(model)
          @subject_syskit_model = model
        end

        # The chosen model, else the described component model, else the
        # enclosing describe block's.
        def subject_syskit_model
          return @subject_syskit_model if @subject_syskit_model

          described = respond_to?(:desc) ? desc : nil
          return described if described.is_a?(Class) && described < AbstractComponent
          return superclass.subject_syskit_model if superclass.respond_to?(:subject_syskit_model)

          raise ArgumentError, 'no subject syskit model: describe a component model ' \
                               '(describe OroGen.library.Task do ... end) or call use_syskit_model'
        end
      end

      def subject_syskit_model
        self.class.subject_syskit_model
      end
    end
  end
end
