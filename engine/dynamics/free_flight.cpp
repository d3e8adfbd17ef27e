#include "engine/dynamics/free_flight.h"

#include <algorithm>
#include <cmath>

namespace rugosim {

namespace {

// Upward speed u = −v·ĝ (m/s) and |g| (m/s²), or nothing when gravity is zero.
struct Vertical {
  double upward_speed = 0.0;
  double g = 0.0;
};

std::optional<Vertical> vertical(const Vec2& velocity, const Vec2& gravity) {
  const double g = gravity.norm();
  if (!(g > 0.0)) return std::nullopt;
  return Vertical{-velocity.dot(gravity) / g, g};
}

}  // namespace

BodyState free_flight(const BodyState& state, const Vec2& gravity, double dt) {
  BodyState next;
  next.position = state.position + state.velocity * dt + (0.5 * dt * dt) * gravity;
  next.velocity = state.velocity + gravity * dt;
  next.angle = state.angle + state.angular_velocity * dt;
  next.angular_velocity = state.angular_velocity;
  return next;
}

BodyState driven_flight(const BodyState& state, const Vec2& acceleration,
                        double angular_acceleration, double dt) {
  BodyState next;
  next.position = state.position + state.velocity * dt + (0.5 * dt * dt) * acceleration;
  next.velocity = state.velocity + acceleration * dt;
  next.angle = state.angle + state.angular_velocity * dt + 0.5 * angular_acceleration * dt * dt;
  next.angular_velocity = state.angular_velocity + angular_acceleration * dt;
  return next;
}

void advance_free_flight(RigidBody& body, const Vec2& gravity, double dt) {
  if (body.fixed()) return;
  body.set_state(free_flight(body.state(), gravity, dt));
}

std::optional<double> apex_time(const Vec2& velocity, const Vec2& gravity) {
  const std::optional<Vertical> v = vertical(velocity, gravity);
  if (!v) return std::nullopt;
  return v->upward_speed / v->g;
}

std::optional<double> apex_rise(const Vec2& velocity, const Vec2& gravity) {
  const std::optional<Vertical> v = vertical(velocity, gravity);
  if (!v) return std::nullopt;
  if (v->upward_speed <= 0.0) return 0.0;
  return v->upward_speed * v->upward_speed / (2.0 * v->g);
}

std::optional<double> time_to_fall(const Vec2& velocity, const Vec2& gravity, double drop) {
  const std::optional<Vertical> v = vertical(velocity, gravity);
  if (!v || !(drop >= 0.0)) return std::nullopt;
  const double u = v->upward_speed;
  const double g = v->g;
  const double s = std::sqrt(u * u + 2.0 * g * drop);
  // Roots of ½g·t² − u·t − drop = 0 are (u ± s)/g. When u < 0, u + s cancels: use the
  // equivalent 2·drop/(s − u) instead, which has no cancellation.
  if (u >= 0.0) return (u + s) / g;
  return 2.0 * drop / (s - u);
}

double motion_bound(const BodyState& state, const Vec2& gravity, double dt, double radius) {
  const double translation = state.velocity.norm() * dt + 0.5 * gravity.norm() * dt * dt;
  const double turn = std::min(std::abs(state.angular_velocity) * dt, 2.0);
  return translation + turn * radius;
}

}  // namespace rugosim
