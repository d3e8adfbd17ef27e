#include "engine/dynamics/slow_contacts.h"

#include <utility>

namespace rugosim {

SlowContactResult solve_slow_contacts(std::span<const SolverBody> bodies,
                                      std::span<SlowContact> contacts,
                                      const SweepSettings& settings) {
  std::vector<VelocityRow> rows(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const SlowContact& c = contacts[i];
    const StartedRow started = start_row(bodies, c.body_a, c.body_b, c.point, c.normal, c.friction);
    rows[i] = started.row;
    VelocityRow& r = rows[i];
    const Vec2& u = started.velocity;
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
