# frozen_string_literal: true

module Syskit
  module Compat
    # Rock's Ruby bindings of Eigen's vectors and rotations
    # (+Eigen::Vector3+, +Eigen::Quaternion+), which model code and tests
    # compute poses with: a composition checking that a pose is within a
    # tolerance of its target subtracts positions and composes rotations.
    # Plain Ruby, with the bindings' method names. The other Eigen classes
    # stay not modelled (see Compat.not_modelled_namespace).
    module Eigen
      # Marks the values a plan may hold as they are (see Types::Type).
      module Value; end

      # A 3D vector of floats.
      class Vector3
        include Value

        attr_accessor :x, :y, :z

        def initialize(x = 0.0, y = 0.0, z = 0.0) # rubocop:disable Naming/MethodParameterName -- Eigen's names
          @x = Float(x)
          @y = Float(y)
          @z = Float(z)
        end

        # rubocop:disable Naming/MethodName -- the bindings' names
        def self.Zero
          new(0, 0, 0)
        end

        # Every coordinate unknown (NaN), as Rock writes an unset vector.
        def self.Unset
          new(Float::NAN, Float::NAN, Float::NAN)
        end

        def self.UnitX
          new(1, 0, 0)
        end

        def self.UnitY
          new(0, 1, 0)
        end

        def self.UnitZ
          new(0, 0, 1)
        end
        # rubocop:enable Naming/MethodName

        def to_a
          [x, y, z]
        end
        alias data to_a

        def [](index)
          to_a.fetch(index)
        end

        def []=(index, value)
          case index
          when 0 then self.x = Float(value)
          when 1 then self.y = Float(value)
          when 2 then self.z = Float(value)
          else raise IndexError, "index #{index} outside of a Vector3 (0 to 2)"
          end
        end

        def size
          3
        end

        def +(other)
          Vector3.new(x + other.x, y + other.y, z + other.z)
        end

        def -(other)
          Vector3.new(x - other.x, y - other.y, z - other.z)
        end

        def -@
          Vector3.new(-x, -y, -z)
        end

        def *(other)
          Vector3.new(x * other, y * other, z * other)
        end

        def /(other)
          Vector3.new(x / other, y / other, z / other)
        end

        def dot(other)
          (x * other.x) + (y * other.y) + (z * other.z)
        end

        def cross(other)
          Vector3.new((y * other.z) - (z * other.y), (z * other.x) - (x * other.z), (x * other.y) - (y * other.x))
        end

        def norm
          Math.sqrt(dot(self))
        end

        def normalize
          self / norm
        end

        def normalize!
          self.x, self.y, self.z = *normalize.to_a
          self
        end

        # Whether each coordinate is within +tolerance+ of +other+'s.
        def approx?(other, tolerance = 1e-6)
          to_a.zip(other.to_a).all? { |a, b| (a - b).abs <= tolerance }
        end

        # Equal coordinates; unknown (NaN) coordinates are equal to each
        # other, as two unset vectors are the same value.
        def ==(other)
          other.is_a?(Vector3) && to_a.zip(other.to_a).all? { |a, b| a == b || (a.nan? && b.nan?) }
        end
        alias eql? ==

        def hash
          to_a.map { |v| v.nan? ? :nan : v }.hash
        end

        def to_s
          "Vector3(#{x}, #{y}, #{z})"
        end
        alias inspect to_s
      end

      # A rotation as a unit quaternion (w, x, y, z).
      class Quaternion
        include Value

        attr_accessor :w, :x, :y, :z

        def initialize(w, x, y, z) # rubocop:disable Naming/MethodParameterName -- Eigen's names
          @w = Float(w)
          @x = Float(x)
          @y = Float(y)
          @z = Float(z)
        end

        def self.Identity # rubocop:disable Naming/MethodName -- the bindings' name
          new(1, 0, 0, 0)
        end

        # The rotation of +angle+ radians around +axis+ (a Vector3).
        def self.from_angle_axis(angle, axis)
          unit = axis.normalize
          half = angle / 2.0
          new(Math.cos(half), *(unit * Math.sin(half)).to_a)
        end

        # The rotation of angles[2] around axis2, then angles[1] around
        # axis1, then angles[0] around axis0 (axes 0, 1, 2 are x, y, z):
        # from_euler(Vector3.new(yaw, pitch, roll), 2, 1, 0).
        def self.from_euler(angles, axis0 = 2, axis1 = 1, axis2 = 0)
          units = [Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ]
          from_angle_axis(angles[0], units.fetch(axis0)) *
            from_angle_axis(angles[1], units.fetch(axis1)) *
            from_angle_axis(angles[2], units.fetch(axis2))
        end

        def self.from_yaw(yaw)
          from_euler(Vector3.new(yaw, 0, 0))
        end

        def to_a
          [w, x, y, z]
        end

        def re
          w
        end

        def im
          [x, y, z]
        end

        # The rotation +other+ then this one (a quaternion), or +other+ (a
        # Vector3) rotated.
        def *(other)
          other.is_a?(Quaternion) ? concatenate(other) : transform(other)
        end

        def concatenate(other) # rubocop:disable Metrics/AbcSize -- the Hamilton product, written out
          aw, ax, ay, az = to_a
          bw, bx, by, bz = other.to_a
          Quaternion.new((aw * bw) - (ax * bx) - (ay * by) - (az * bz),
                         (aw * bx) + (ax * bw) + (ay * bz) - (az * by),
                         (aw * by) - (ax * bz) + (ay * bw) + (az * bx),
                         (aw * bz) + (ax * by) - (ay * bx) + (az * bw))
        end

        def transform(vector)
          rotated = self * Quaternion.new(0, *vector.to_a) * inverse
          Vector3.new(rotated.x, rotated.y, rotated.z)
        end

        def conjugate
          Quaternion.new(w, -x, -y, -z)
        end

        def inverse
          squared = to_a.sum { |v| v * v }
          Quaternion.new(w / squared, -x / squared, -y / squared, -z / squared)
        end

        def normalize
          length = Math.sqrt(to_a.sum { |v| v * v })
          Quaternion.new(*to_a.map { |v| v / length })
        end

        def normalize!
          self.w, self.x, self.y, self.z = *normalize.to_a
          self
        end

        # Yaw, pitch and roll (rotations around z, y then x) as a Vector3:
        # yaw in (-pi, pi], pitch in [-pi/2, pi/2], roll in (-pi, pi].
        def to_euler
          qw, qx, qy, qz = to_a
          sin_pitch = (2.0 * ((qw * qy) - (qz * qx))).clamp(-1.0, 1.0)
          Vector3.new(Math.atan2(2.0 * ((qw * qz) + (qx * qy)), 1.0 - (2.0 * ((qy * qy) + (qz * qz)))),
                      Math.asin(sin_pitch),
                      Math.atan2(2.0 * ((qw * qx) + (qy * qz)), 1.0 - (2.0 * ((qx * qx) + (qy * qy)))))
        end

        def yaw
          to_euler[0]
        end

        def pitch
          to_euler[1]
        end

        def roll
          to_euler[2]
        end

        # The angle in [0, pi] and the axis of this rotation.
        def to_angle_axis(eps = 1e-12)
          length = Math.sqrt((x * x) + (y * y) + (z * z))
          return [0.0, Vector3.UnitZ] if length < eps

          [2.0 * Math.atan2(length, w), Vector3.new(x, y, z) / length]
        end

        def approx?(other, tolerance = 1e-6)
          to_a.zip(other.to_a).all? { |a, b| (a - b).abs <= tolerance }
        end

        def ==(other)
          other.is_a?(Quaternion) && to_a == other.to_a
        end
        alias eql? ==

        def hash
          to_a.hash
        end

        def to_s
          "Quaternion(#{w}, (#{x}, #{y}, #{z}))"
        end
        alias inspect to_s
      end
    end
  end
end
