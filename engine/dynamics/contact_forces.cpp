#include "engine/dynamics/contact_forces.h"

namespace rugosim {

ForceResult solve_contact_forces(std::span<const ForceBody> bodies,
                                 std::span<ForceContact> contacts, const Vec2& gravity, double h,
                                 const ForceSettings& settings) {
  const auto movable = [&](std::size_t i) { return bodies[i].inverse_mass > 0.0; };
  std::vector<VelocityRow> rows(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ForceContact& c = contacts[i];
    const StartedRow started = start_row(bodies, c.body_a, c.body_b, c.point, c.normal, c.friction);
    rows[i] = started.row;
    VelocityRow& r = rows[i];
    const Vec2& w = started.velocity;
    const Vec2 a_g =
        (movable(c.body_a) ? gravity : Vec2::Zero()) - (movable(c.body_b) ? gravity : Vec2::Zero());
    const Vec2 tangent = perp(c.normal);
    // s + h·w_n + ½h²·a_g,n + ½h·(Kφ)_n ≥ 0  ⇔  (Kφ)_n ≥ −2(s/h + w_n) − h·a_g,n.
    r.normal_target = -2.0 * (c.gap / h + w.dot(c.normal)) - h * a_g.dot(c.normal);
    r.tangent_target = -(w.dot(tangent) + h * a_g.dot(tangent));
    r.impulse = c.force * h;  // warm start: last step's force over this step
  }

  const RowSolution solution = solve_velocity_rows(
      bodies, rows, SweepSettings{settings.max_sweeps, settings.tolerance, gravity.norm() * h});

  ForceResult result;
  result.sweeps = solution.sweeps;
  result.residual = solution.residual;
  result.converged = solution.converged;
  result.acceleration.assign(bodies.size(), Vec2::Zero());
  result.angular_acceleration.assign(bodies.size(), 0.0);
  for (std::size_t i = 0; i < contacts.size(); ++i)
    contacts[i].force = rows[i].impulse / h;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!movable(i)) continue;
    result.acceleration[i] = gravity + solution.change[i].velocity / h;
    result.angular_acceleration[i] = solution.change[i].angular_velocity / h;
  }
  return result;
}

}  // namespace rugosim
