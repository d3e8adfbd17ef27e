#include "engine/dynamics/mid_step_rest.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/dynamics/slow_contacts.h"
#include "engine/geometry/friction.h"

namespace rugosim {

SweepSettings rest_sweep_settings(const Vec2& gravity, double max_step, int max_sweeps) {
  SweepSettings sweeps;
  sweeps.max_sweeps = max_sweeps;
  sweeps.tolerance = 1e-6;
  sweeps.speed_floor = gravity.norm() * max_step;
  return sweeps;
}

const RestedPair* find_rested(std::span<const RestedPair> rested, std::size_t a, std::size_t b) {
  const auto it =
      std::lower_bound(rested.begin(), rested.end(), std::make_pair(a, b),
                       [](const RestedPair& r, const std::pair<std::size_t, std::size_t>& key) {
                         return std::make_pair(r.body_a, r.body_b) < key;
                       });
  if (it == rested.end() || it->body_a != a || it->body_b != b) return nullptr;
  return &*it;
}

MidStepRestCounts rest_at_mid_step(std::span<RigidBody> bodies, std::span<const std::uint8_t> moves,
                                   std::span<const ContactManifold> manifolds, double h,
                                   const MidStepRestSettings& settings) {
  MidStepRestCounts counts;
  std::vector<SlowContact> contacts;
  const double g = settings.gravity.norm();
  for (const ContactManifold& m : manifolds) {
    if (m.state() != PairState::kContact) continue;
    if (moves[m.body_a] == 0 && moves[m.body_b] == 0) continue;
    const RigidBody& a = bodies[m.body_a];
    const RigidBody& b = bodies[m.body_b];
    const double min_band = a.shape().min_band() + b.shape().min_band();
    counts.rested.push_back({m.body_a, m.body_b, 0.0});
    for (const Contact& c : m.contacts) {
      SlowContact s;
      s.body_a = m.body_a;
      s.body_b = m.body_b;
      s.point = c.point;
      s.normal = c.normal;
      const double band = std::max(c.lambda_a + c.lambda_b, min_band);
      const double rest_gap = (1.0 - settings.rest_depth) * band;
      s.allowance = std::max(0.0, c.distance - rest_gap) / h;
      if (settings.lift && c.distance < rest_gap && g > 0.0)
        s.allowance = (c.distance - rest_gap) / std::max(std::sqrt(2.0 * band / g), h);
      counts.rested.back().allowance = std::max(counts.rested.back().allowance, s.allowance);
      s.friction =
          contact_friction(a.friction_coefficient(c.segment_a, c.t_a, settings.friction_gain),
                           b.friction_coefficient(c.segment_b, c.t_b, settings.friction_gain));
      contacts.push_back(s);
    }
  }
  if (contacts.empty()) return counts;

  // Only the bodies the contacts name enter the solve; the rest keep index order for it.
  std::vector<SolverBody> solver(bodies.size());
  const Vec2 half_kick = 0.5 * h * settings.gravity;
  for (const SlowContact& s : contacts) {
    for (const std::size_t i : {s.body_a, s.body_b}) {
      const RigidBody& body = bodies[i];
      SolverBody& sb = solver[i];
      sb.position = body.state().position;
      sb.velocity = body.state().velocity;
      sb.angular_velocity = body.state().angular_velocity;
      if (moves[i] != 0) {
        sb.inverse_mass = body.inverse_mass();
        sb.inverse_inertia = body.inverse_inertia();
        sb.velocity += half_kick;
      }
    }
  }
  const SlowContactResult result = solve_slow_contacts(solver, contacts, settings.sweeps);
  counts.contacts = contacts.size();
  counts.pushed = result.pushed;
  counts.sweeps = static_cast<std::uint64_t>(result.sweeps);
  counts.converged = result.converged;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (moves[i] == 0) continue;
    const VelocityChange& d = result.change[i];
    if (d.velocity == Vec2::Zero() && d.angular_velocity == 0.0) continue;
    BodyState state = bodies[i].state();
    state.velocity += d.velocity;
    state.angular_velocity += d.angular_velocity;
    bodies[i].set_state(state);
  }
  return counts;
}

}  // namespace rugosim
