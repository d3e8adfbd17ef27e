#include "engine/dynamics/step_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rugosim {
namespace {

Aabb grown(Aabb box, double by) {
  box.min -= Vec2::Constant(by);
  box.max += Vec2::Constant(by);
  return box;
}

// m/s: a bound on how fast any boundary point of a moves relative to any boundary point of b.
double relative_boundary_speed(const RigidBody& a, const RigidBody& b) {
  return (a.state().velocity - b.state().velocity).norm() +
         std::abs(a.state().angular_velocity) * a.bounding_radius() +
         std::abs(b.state().angular_velocity) * b.bounding_radius();
}

}  // namespace

bool StepPlanner::nothing_can_meet(std::span<const RigidBody> bodies,
                                   std::span<const std::uint8_t> moves, const Vec2& gravity,
                                   double h) {
  Vec2 mean = Vec2::Zero();
  double movers = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (moves[i] == 0) continue;
    mean += bodies[i].state().velocity;
    movers += 1.0;
  }
  if (movers == 0.0) return true;
  mean /= movers;
  const double still_sweep = mean.norm() * h + 0.5 * gravity.norm() * h * h;
  proxies_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBody& b = bodies[i];
    const BodyState& s = b.state();
    const double sweep = moves[i] != 0
                             ? (s.velocity - mean).norm() * h +
                                   std::abs(s.angular_velocity) * b.shape().tree().reach() * h
                             : still_sweep;
    proxies_[i].box = grown(b.shape().world_bounds(b.placement()), sweep);
    proxies_[i].fixed = b.fixed();
    proxies_[i].asleep = !b.fixed() && moves[i] == 0;
  }
  return broad_phase_.find_pairs(proxies_).empty();
}

double StepPlanner::tunnel_free(std::span<const RigidBody> bodies,
                                std::span<const std::uint8_t> moves, const Vec2& gravity, double h,
                                double min_step) {
  const double g = gravity.norm();
  double thinnest = std::numeric_limits<double>::infinity();
  double fastest = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    thinnest = std::min(thinnest, bodies[i].thickness());
    if (moves[i] != 0) fastest = std::max(fastest, bodies[i].boundary_speed());
  }
  // Every pair together moves at most twice the fastest body's reach.
  if (2.0 * (fastest * h + 0.5 * g * h * h) <= 0.5 * thinnest) return h;
  const double safe = longest_step(bodies, moves, g, h, [&](std::size_t i, std::size_t j) {
    return 0.5 * std::min(bodies[i].thickness(), bodies[j].thickness());
  });
  // Never below min_step (speeds beyond that are refused by the scene layer), never above h.
  return std::min(h, std::max(safe, min_step));
}

double StepPlanner::gentle_step(std::span<const RigidBody> bodies,
                                std::span<const std::uint8_t> moves, const Vec2& gravity, double h,
                                double band_share) {
  return longest_step(bodies, moves, gravity.norm(), h, [&](std::size_t i, std::size_t j) {
    return band_share * (bodies[i].shape().least_band() + bodies[j].shape().least_band());
  });
}

template <typename PairLimit>
double StepPlanner::longest_step(std::span<const RigidBody> bodies,
                                 std::span<const std::uint8_t> moves, double g, double h,
                                 const PairLimit& pair_limit) {
  // Candidate pairs: boxes grown by each mover's own reach (speed and gravity) meet whenever a
  // pair's relative reach below could, so the sweep finds every pair that test would.
  boxes_.resize(bodies.size());
  proxies_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBody& b = bodies[i];
    boxes_[i] = b.shape().world_bounds(b.placement());
    const double reach = moves[i] != 0 ? b.boundary_speed() * h + 0.5 * g * h * h : 0.0;
    proxies_[i].box = grown(boxes_[i], reach);
    proxies_[i].fixed = b.fixed();
    proxies_[i].asleep = !b.fixed() && moves[i] == 0;
  }
  double safe = h;
  for (const BodyPair& pair : broad_phase_.find_pairs(proxies_)) {
    // Seen from a body that moves.
    const std::size_t i = moves[pair.a] != 0 ? pair.a : pair.b;
    const std::size_t j = i == pair.a ? pair.b : pair.a;
    const bool j_moves = moves[j] != 0;
    // Relative motion: any two boundary points of i and j part or approach at most at
    // |v_i − v_j| + |ω_i|·r_i + |ω_j|·r_j (u_i − u_j = v_i − v_j + ω_i × r_i − ω_j × r_j), and
    // gravity moves both alike when both move. Bodies falling together, however fast, do not
    // hold each other to short steps.
    const double a =
        j_moves ? relative_boundary_speed(bodies[i], bodies[j]) : bodies[i].boundary_speed();
    const double b = j_moves ? 0.0 : 0.5 * g;
    const double reach = a * h + b * h * h;
    const double limit = pair_limit(i, j);
    if (reach <= limit) continue;
    if (!grown(boxes_[i], reach).overlaps(boxes_[j])) continue;
    // The largest dt with a·dt + b·dt² <= limit.
    const double dt = b > 0.0 ? 2.0 * limit / (a + std::sqrt(a * a + 4.0 * b * limit)) : limit / a;
    safe = std::min(safe, dt);
  }
  return safe;
}

}  // namespace rugosim
