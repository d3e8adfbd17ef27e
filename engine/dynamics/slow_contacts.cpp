#include "engine/dynamics/slow_contacts.h"

#include <utility>

#include "engine/dynamics/collision_impulse.h"

namespace rugosim {

SlowContactResult solve_slow_contacts(std::span<const SolverBody> bodies,
                                      std::span<SlowContact> contacts,
                                      const SweepSettings& settings) {
  std::vector<VelocityRow> rows(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const SlowContact& c = contacts[i];
    VelocityRow& r = rows[i];
    const SolverBody& a = bodies[c.body_a];
    const SolverBody& b = bodies[c.body_b];
    r.body_a = c.body_a;
    r.body_b = c.body_b;
    r.point = c.point;
    r.normal = c.normal;
    r.friction = c.friction;
    const ContactBodyState sa{a.inverse_mass, a.inverse_inertia, a.velocity, a.angular_velocity,
                              c.point - a.position};
    const ContactBodyState sb{b.inverse_mass, b.inverse_inertia, b.velocity, b.angular_velocity,
                              c.point - b.position};
    const Vec2 u = relative_contact_velocity(sa, sb);
    r.normal_target = -c.allowance - u.dot(c.normal);
    r.tangent_target = -u.dot(perp(c.normal));
    r.impulse = c.impulse;
  }
  RowSolution solution = solve_velocity_rows(bodies, rows, settings);
  SlowContactResult result;
  result.change = std::move(solution.change);
  result.sweeps = solution.sweeps;
  result.residual = solution.residual;
  result.converged = solution.converged;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    contacts[i].impulse = rows[i].impulse;
    if (rows[i].impulse.x() > 0.0) ++result.pushed;
  }
  return result;
}

}  // namespace rugosim
