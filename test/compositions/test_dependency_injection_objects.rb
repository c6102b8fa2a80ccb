# frozen_string_literal: true

require 'helper'

module Syskit
  # DependencyInjection as Syskit's tests and plugins handle it directly: a
  # changeable table of selections (add, add_mask, clear), its functions
  # (normalize_selection, resolve_recursive_selection_mapping,
  # resolve_default_selections, find_name_resolution), what it selects for
  # a child (selection_for), and a context of layers (push, pop).
  class TestDependencyInjectionObjects < Minitest::Test
    def setup
      super
      @pose = pose = DataService.new_submodel(name: 'Pose')
      @odometry = DataService.new_submodel(name: 'Odometry') { provides pose }
      @gps = Component.new_submodel(name: 'Gps') { provides pose, as: 'fix' }
      @twice = Component.new_submodel(name: 'Twice') do
        provides pose, as: 'front'
        provides pose, as: 'rear'
      end
    end

    def test_it_is_built_from_defaults_and_keyed_selections_and_changed_by_add
      injection = DependencyInjection.new(@gps, 'child' => @twice)
      assert_equal({ 'child' => @twice }, injection.explicit)
      assert_equal Set[@gps], injection.defaults
      injection.add('other' => @gps)
      assert_equal %w[child other], injection.explicit.keys
      assert injection.clear.empty?
      assert DependencyInjection::EMPTY.frozen?
      refute DependencyInjection::EMPTY.dup.add(@gps).empty?
    end

    def test_a_model_selected_for_itself_keeps_what_it_selects
      injection = DependencyInjection.new(@pose => @odometry)
      injection.add(@pose => @pose)
      assert_equal({ @pose => @odometry }, injection.explicit)
    end

    def test_a_mask_stops_selections_by_name
      injection = DependencyInjection.new.add_mask(['child'])
      assert_same DependencyInjection.do_not_inherit, injection.explicit['child']
    end

    def test_a_component_selected_for_a_service_is_narrowed_to_that_service
      assert_equal({ @pose => @gps.fix_srv }, DependencyInjection.normalize_selection(@pose => @gps))
      assert_equal({ @gps => @gps }, DependencyInjection.normalize_selection(@gps => @gps.fix_srv))
      assert_raises(AmbiguousServiceSelection) { DependencyInjection.normalize_selection(@pose => @twice) }
    end

    def test_a_task_selected_for_a_service_is_narrowed_to_its_service
      task = @gps.new
      assert_equal({ @pose => task.fix_srv }, DependencyInjection.normalize_selection(@pose => task))
      assert_raises(ArgumentError) { DependencyInjection.normalize_selection(@twice => task) }
    end

    def test_selections_must_fullfill_their_key_and_keys_be_names_or_models
      assert_raises(ArgumentError) { DependencyInjection.normalize_selection(@gps => @twice) }
      assert_raises(ArgumentError) { DependencyInjection.normalize_selection(@odometry => @pose) }
      assert_raises(ArgumentError) { DependencyInjection.normalize_selection(Object.new => @gps) }
      assert_raises(ArgumentError) { DependencyInjection.normalize_selection('child' => Object.new) }
      assert_equal({ 'child' => 'other' }, DependencyInjection.normalize_selection('child' => 'other'))
    end

    def test_chains_are_followed_names_are_not
      sub = @gps.new_submodel(name: 'SubGps')
      resolved = DependencyInjection.resolve_recursive_selection_mapping(
        'a' => @pose, @pose => @gps.fix_srv, @gps => sub, 'b' => 'a'
      )
      assert_equal sub.fix_srv, resolved['a']
      assert_equal 'a', resolved['b']
    end

    def test_defaults_select_themselves_for_what_they_provide_once
      resolved = DependencyInjection.resolve_default_selections({}, [@gps, @twice])
      assert_same @gps, resolved[@pose], 'Twice provides Pose twice: it is no default for it'
      assert_equal [@gps, @twice], [resolved[@gps], resolved[@twice]]
      assert_equal({ @pose => @gps }, DependencyInjection.resolve_default_selections({}, [@gps]).slice(@pose))
      refute DependencyInjection.resolve_default_selections({}, [@gps, @gps.new_submodel]).key?(@pose)
      assert_equal({ @pose => 'x', @gps => @gps, AbstractComponent => @gps },
                   DependencyInjection.resolve_default_selections({ @pose => 'x' }, [@gps]))
    end

    def test_names_resolve_to_selections_and_their_services
      assert_equal @gps.fix_srv, DependencyInjection.find_name_resolution('nav.fix', 'nav' => @gps)
      assert_nil DependencyInjection.find_name_resolution('nav', 'nav' => 'other')
      assert_raises(NameResolutionError) { DependencyInjection.find_name_resolution('nav.x', 'nav' => @gps) }
      assert_raises(NameResolutionError) { DependencyInjection.find_name_resolution('nav.x', 'nav' => @pose) }
      injection = DependencyInjection.new('child' => 'nav.fix')
      assert_empty injection.resolve_names('nav' => @gps)
      assert_equal({ 'child' => @gps.fix_srv }, injection.explicit)
    end

    def test_selection_for_a_child_by_name_then_by_model
      injection = DependencyInjection.new('child' => @gps, @pose => @twice.front_srv)
      _, by_name, services, used = injection.selection_for('child', @pose)
      assert_equal [[@gps], Set['child']], [by_name.models, used]
      assert_empty services
      _, by_model, services, used = injection.selection_for('other', @pose)
      assert_equal [[@twice], { @pose => @twice.front_srv }, Set[@pose]], [by_model.models, services, used]
      _, nothing, = DependencyInjection.new('child' => DependencyInjection.nothing).selection_for('child', @pose)
      assert_equal @pose.placeholder_model, nothing.model
    end

    def test_selections_of_unrelated_component_models_are_incompatible
      injection = DependencyInjection.new(@pose => @gps)
      assert_raises(IncompatibleComponentModels) do
        injection.selection_for(nil, InstanceRequirements.new([@twice, @pose]))
      end
    end

    def test_a_selected_task_is_returned_with_its_requirements
      task = @gps.new
      instance, requirements, services, = DependencyInjection.new('child' => task.fix_srv).selection_for('child', @pose)
      assert_same task, instance
      assert_equal InstanceRequirements.new([@gps]), requirements
      assert_equal({ @pose => @gps.fix_srv }, services)
    end

    def test_a_context_stacks_layers
      context = DependencyInjectionContext.new
      context.push(DependencyInjection.new(@pose => @gps))
      context.push(DependencyInjection.new('child' => @pose))
      assert_equal @gps.fix_srv, context.current_state.explicit['child']
      context.pop
      refute context.current_state.explicit.key?('child')
    end
  end
end
