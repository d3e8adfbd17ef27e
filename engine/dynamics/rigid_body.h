// A rigid lamina bounded by a closed periodic cubic B-spline (paper §2, §4): its boundary and
// tolerance band (shared, never changed once built), its mass properties, its material and its
// state of motion.
//
// Frames. The user gives control points in a body frame of their choosing and places that
// frame's origin in the world. Dynamics wants the centre of mass as the reference point (then
// free flight separates into a parabola and a constant spin, and velocity_at is v + ω⊥r), so
// the body re-centres its curve on the centroid: the "body frame" below is the user's frame
// shifted by the centroid c, and the placement is (θ, x_com). The user's origin sits at body
// point −c, in the world at x_com + R(θ)·(−c).
#pragma once

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include "engine/collision/collision_shape.h"
#include "engine/core/transform.h"
#include "engine/core/types.h"
#include "engine/dynamics/material.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {

// Where a body is and how it moves. The reference point is the centre of mass.
struct BodyState {
  Vec2 position = Vec2::Zero();   // m, centre of mass in the world
  double angle = 0.0;             // rad, counter-clockwise, not wrapped (it counts turns)
  Vec2 velocity = Vec2::Zero();   // m/s, of the centre of mass
  double angular_velocity = 0.0;  // rad/s, counter-clockwise
};

// Everything a body is built from, as the scene gives it.
struct RigidBodyDesc {
  // m, in the user's body frame; at least 4, a simple closed curve, either orientation.
  std::vector<Vec2> control_points;
  // m, roughness σ_j of input segment j (segment j uses control points j−1..j+2); one per
  // control point, or empty for σ = 0 everywhere.
  std::vector<double> sigma;
  double q = 0.9;  // dimensionless, λ_j = q·σ_j, 0 < q <= 1 (paper §2.2)
  Material material;
  bool fixed = false;             // a fixed body never moves and has infinite mass for impulses
  Vec2 position = Vec2::Zero();   // m, where the user's body-frame origin is placed
  double angle = 0.0;             // rad, counter-clockwise
  Vec2 velocity = Vec2::Zero();   // m/s, of the centre of mass; zero when fixed
  double angular_velocity = 0.0;  // rad/s, counter-clockwise; zero when fixed
};

class RigidBody {
 public:
  // Normalises the boundary to counter-clockwise (σ follows its segments), checks it is a
  // simple closed curve enclosing an area, computes its mass properties and re-centres it on
  // its centroid. Throws std::invalid_argument with the reason on a bad boundary, σ, q or
  // material, or a fixed body given a velocity.
  explicit RigidBody(const RigidBodyDesc& desc);

  // Copies share the collision shape (boundary, band and tree): identical bodies cost one.

  // Boundary, tolerances and tree in the body frame (centroid at the origin).
  const CollisionShape& shape() const { return *shape_; }
  const std::shared_ptr<const CollisionShape>& shared_shape() const { return shape_; }
  const PeriodicBSpline& curve() const { return shape_->curve(); }
  const Material& material() const { return material_; }

  bool fixed() const { return fixed_; }
  double area() const { return area_; }                  // m²
  double mass() const { return mass_; }                  // kg, density × area, even when fixed
  double inertia() const { return inertia_; }            // kg·m², about the centre of mass
  double inverse_mass() const { return inverse_mass_; }  // 1/kg, 0 when fixed
  double inverse_inertia() const { return inverse_inertia_; }  // 1/(kg·m²), 0 when fixed

  // m: the centroid in the user's body frame, which is what was subtracted from the control
  // points to make the body frame.
  const Vec2& centroid_offset() const { return centroid_offset_; }
  // m: radius of a disc about the centre of mass that holds the whole curve (not its band):
  // the largest control point distance, since the curve lies in their convex hull.
  double bounding_radius() const { return bounding_radius_; }
  // m: 2 × area / perimeter, the width of a strip with the body's area and outline: for a
  // convex body at most its least width (a disk of radius r gives r, a thin plate its
  // thickness), so that moving less than half of it a body cannot pass through another
  // unseen (World's tunnelling bound). For a concave body it is an average: a thin arm of a
  // thick body is thinner than this, and something small and fast could still pass through
  // the arm alone.
  double thickness() const { return thickness_; }
  // m/s: |v| + |ω| × bounding radius, the fastest any point of the boundary moves.
  double boundary_speed() const {
    return state_.velocity.norm() + std::abs(state_.angular_velocity) * bounding_radius_;
  }

  // Stored segment k (counter-clockwise numbering) at t is the input's segment
  // input_segment(k) at t, or at 1 − t when the input ran clockwise (input_reversed()).
  std::size_t input_segment(std::size_t k) const { return input_segment_of_[k]; }
  bool input_reversed() const { return input_reversed_; }
  // The same place on the curve named in the input's segment numbering, t in [0, 1).
  CurveParam to_input_param(const CurveParam& stored) const;

  const BodyState& state() const { return state_; }
  // Throws std::invalid_argument when a fixed body is given a velocity.
  void set_state(const BodyState& state);
  // Puts the user's body-frame origin at `origin` (m) with the frame turned by `angle` (rad).
  void place_origin(const Vec2& origin, double angle);

  // Body frame → world: rotation by the angle, then translation to the centre of mass.
  const Transform2& placement() const { return placement_; }
  // m: where the user's body-frame origin is now, x_com + R(θ)·(−c).
  Vec2 origin_position() const { return placement_.apply(-centroid_offset_); }
  // m: a body-frame point (centroid frame, as in curve()) in the world.
  Vec2 world_point(const Vec2& body_point) const { return placement_.apply(body_point); }
  // m/s: velocity of the body's material point now at world point p, v + ω⊥(p − x_com).
  Vec2 velocity_at(const Vec2& world_point) const {
    return state_.velocity + state_.angular_velocity * perp(world_point - state_.position);
  }
  // J per unit thickness: ½mv² + ½Iω² (0 for a fixed body, which does not move).
  double kinetic_energy() const;

  // Dimensionless μ at parameter t of stored segment k (paper §4.2): from the interpolated
  // tolerance λ_k(t), the material's λ_min and the world's friction gain k (1/m).
  double friction_coefficient(std::size_t segment, double t, double friction_gain) const;

 private:
  std::shared_ptr<const CollisionShape> shape_;
  Material material_;
  bool fixed_ = false;
  double area_ = 0.0;                    // m²
  double mass_ = 0.0;                    // kg
  double inertia_ = 0.0;                 // kg·m²
  double inverse_mass_ = 0.0;            // 1/kg
  double inverse_inertia_ = 0.0;         // 1/(kg·m²)
  Vec2 centroid_offset_ = Vec2::Zero();  // m, in the user's frame
  double bounding_radius_ = 0.0;         // m
  double thickness_ = 0.0;               // m
  std::vector<std::size_t> input_segment_of_;
  bool input_reversed_ = false;
  BodyState state_;
  Transform2 placement_;  // kept in step with state_: queries need it far more than updates
};

}  // namespace rugosim
