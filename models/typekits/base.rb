# Rock's base typekit (base/types). The types that configure code and tests
# build are described with their fields, and with the constructors Rock's
# Ruby bindings give them; every other /base/ type is accepted as opaque.
accept_unknown_types

struct 'Time' do
  field 'microseconds', '/int64_t'
end

specialize_model 'Time' do
  def now
    new(microseconds: (::Time.now.to_r * 1_000_000).to_i)
  end
end

# Rock's Ruby code writes a Ruby Time wherever a /base/Time goes.
convert_from_ruby ::Time, 'Time' do |time|
  new(microseconds: (time.to_r * 1_000_000).to_i)
end

# Loaded with the base typekit in Rock: Base.unknown, Base.unset (NaN).
ruby_library 'base/float'

# Scalars whose value is NaN when unknown.
struct 'Angle' do
  field 'rad', '/double', unknown: true
end

struct 'Temperature' do
  field 'kelvin', '/double', unknown: true
end

struct 'Pressure' do
  field 'pascal', '/float', unknown: true
end

struct 'samples/Temperature' do
  field 'kelvin', '/double', unknown: true
  field 'time', '/base/Time'
end

struct 'samples/Pressure' do
  field 'pascal', '/float', unknown: true
  field 'time', '/base/Time'
end

# The state of one joint: what is not known (or not commanded) is NaN.
struct 'JointState' do
  %w[position speed effort raw acceleration].each { |f| field f, '/double', unknown: true }
end

# JointState.Speed(2.0): a state where only the speed is known.
specialize_model 'JointState' do
  %w[position speed effort raw acceleration].each do |f|
    define_method(f.capitalize) { |value| new(f.to_sym => value) }
  end
end

struct 'JointLimitRange' do
  field 'min', '/base/JointState'
  field 'max', '/base/JointState'
end

# Named vectors: names, and one element per name.
struct 'JointLimits' do
  field 'names', '/std/vector</std/string>'
  field 'elements', '/std/vector</base/JointLimitRange>'
end

struct 'samples/Joints' do
  field 'names', '/std/vector</std/string>'
  field 'elements', '/std/vector</base/JointState>'
  field 'time', '/base/Time'
end

# Joints.from_positions(1, 2): one joint per value, only that quantity known.
specialize_model 'samples/Joints' do
  { from_positions: 'position', from_speeds: 'speed', from_efforts: 'effort', from_raws: 'raw',
    from_accelerations: 'acceleration' }.each do |constructor, f|
    define_method(constructor) do |*values|
      state = fields.fetch('elements').element
      new(elements: values.map { |v| state.new(f.to_sym => v) })
    end
  end
end

# Typedefs of Rock's base types: a joint command is a joint sample.
alias_type 'commands/Joints', 'samples/Joints'

# Eigen's types are opaque here: values of Rock's Eigen bindings, or plain data.
struct 'Pose' do
  field 'position', '/base/Vector3d'
  field 'orientation', '/base/Quaterniond'
end

struct 'samples/RigidBodyState' do
  field 'time', '/base/Time'
  field 'sourceFrame', '/std/string'
  field 'targetFrame', '/std/string'
  field 'position', '/base/Vector3d'
  field 'cov_position', '/base/Matrix3d'
  field 'orientation', '/base/Quaterniond'
  field 'cov_orientation', '/base/Matrix3d'
  field 'velocity', '/base/Vector3d'
  field 'cov_velocity', '/base/Matrix3d'
  field 'angular_velocity', '/base/Vector3d'
  field 'cov_angular_velocity', '/base/Matrix3d'
end

# RigidBodyState.Invalid: nothing known (Rock fills it with NaN; here the
# opaque fields stay unset).
specialize_model 'samples/RigidBodyState' do
  def invalid
    new
  end
  alias_method :Invalid, :invalid
end

# A command on the six axes of a body (controllers' setpoints): what is not
# commanded is NaN.
struct 'LinearAngular6DCommand' do
  field 'time', '/base/Time'
  field 'linear', '/base/Vector3d'
  field 'angular', '/base/Vector3d'
end
