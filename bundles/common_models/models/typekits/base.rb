# Rock's base typekit. Only the types the bundled models use are described;
# the others (base/samples/RigidBodyState, ...) are accepted as opaque.
accept_unknown_types

struct 'Time' do
  field 'microseconds', '/int64_t'
end

# Typedefs of Rock's base types: a joint command is a joint sample.
alias_type 'commands/Joints', 'samples/Joints'
