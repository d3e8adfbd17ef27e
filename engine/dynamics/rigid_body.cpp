#include "engine/dynamics/rigid_body.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "engine/geometry/boundary_validity.h"
#include "engine/geometry/curve_length.h"
#include "engine/geometry/friction.h"
#include "engine/geometry/mass_properties.h"
#include "engine/geometry/orientation.h"
#include "engine/geometry/tolerance_profile.h"

namespace rugosim {

namespace {

bool finite(const Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

// Checks of the description that need no geometry; the boundary is checked once normalised.
void check_desc(const RigidBodyDesc& desc) {
  if (const std::string why = desc.material.validate(); !why.empty())
    throw std::invalid_argument("material: " + why);
  if (!desc.sigma.empty() && desc.sigma.size() != desc.control_points.size()) {
    throw std::invalid_argument(
        "sigma has " + std::to_string(desc.sigma.size()) + " values but the boundary has " +
        std::to_string(desc.control_points.size()) + " segments (one per control point)");
  }
  if (!finite(desc.position) || !std::isfinite(desc.angle))
    throw std::invalid_argument("the position and angle must be finite");
  if (!finite(desc.velocity) || !std::isfinite(desc.angular_velocity))
    throw std::invalid_argument("the velocity and angular velocity must be finite");
}

void check_fixed_at_rest(bool fixed, const Vec2& velocity, double angular_velocity) {
  // A moving fixed body would push others with infinite mass yet never move itself: its
  // velocity would be a lie told to the impulse solver, so refuse it rather than ignore it.
  if (fixed && (velocity != Vec2::Zero() || angular_velocity != 0.0))
    throw std::invalid_argument("a fixed body cannot move: its velocities must be zero");
}

}  // namespace

RigidBody::RigidBody(const RigidBodyDesc& desc) : material_(desc.material), fixed_(desc.fixed) {
  check_desc(desc);
  check_fixed_at_rest(desc.fixed, desc.velocity, desc.angular_velocity);

  // Throws on fewer than 4 or non-finite points.
  Reversal ccw = make_counter_clockwise(desc.control_points);
  const PeriodicBSpline user_curve(ccw.control_points);
  if (const ValidityReport report = check_boundary(user_curve); !report.valid)
    throw std::invalid_argument("invalid boundary: " + report.reason);

  const std::vector<double> input_sigma =
      desc.sigma.empty() ? std::vector<double>(desc.control_points.size(), 0.0) : desc.sigma;
  const std::vector<double> sigma = follow_segments(ccw, std::span<const double>(input_sigma));
  ToleranceProfile tolerances = ToleranceProfile::from_sigma(sigma, desc.q);

  const MassProperties props = compute_mass_properties(user_curve);
  area_ = props.area;
  mass_ = props.mass(material_.density);
  inertia_ = props.inertia(material_.density);
  inverse_mass_ = fixed_ ? 0.0 : 1.0 / mass_;
  inverse_inertia_ = fixed_ ? 0.0 : 1.0 / inertia_;
  centroid_offset_ = props.centroid;

  std::vector<Vec2> centred = std::move(ccw.control_points);
  for (Vec2& p : centred) {
    p -= centroid_offset_;
    bounding_radius_ = std::max(bounding_radius_, p.norm());
  }
  shape_ = std::make_shared<const CollisionShape>(PeriodicBSpline(std::move(centred)),
                                                  std::move(tolerances));
  thickness_ = 2.0 * area_ / curve_length(shape_->curve());
  input_segment_of_ = std::move(ccw.old_segment_of);
  input_reversed_ = ccw.reversed;

  place_origin(desc.position, desc.angle);
  state_.velocity = desc.velocity;
  state_.angular_velocity = desc.angular_velocity;
}

CurveParam RigidBody::to_input_param(const CurveParam& stored) const {
  const std::size_t old = input_segment_of_[stored.segment];
  if (!input_reversed_) return {old, stored.t};
  const double t = 1.0 - stored.t;
  // The end of an input segment is the start of the next one: keep t in [0, 1).
  if (t >= 1.0) return {(old + 1) % input_segment_of_.size(), 0.0};
  return {old, t};
}

void RigidBody::set_state(const BodyState& state) {
  check_fixed_at_rest(fixed_, state.velocity, state.angular_velocity);
  state_ = state;
  placement_ = Transform2(state_.angle, state_.position);
}

void RigidBody::place_origin(const Vec2& origin, double angle) {
  BodyState s = state_;
  s.angle = angle;
  // The user's origin is body point −c, so the centre of mass sits at origin + R(θ)·c.
  s.position = origin + Transform2(angle, Vec2::Zero()).rotate(centroid_offset_);
  set_state(s);
}

double RigidBody::kinetic_energy() const {
  return 0.5 * mass_ * state_.velocity.squaredNorm() +
         0.5 * inertia_ * state_.angular_velocity * state_.angular_velocity;
}

double RigidBody::friction_coefficient(std::size_t segment, double t, double friction_gain) const {
  return rugosim::friction_coefficient(shape_->tolerances().at(segment, t), material_.lambda_min,
                                       friction_gain);
}

}  // namespace rugosim
