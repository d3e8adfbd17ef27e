// Paper §4.3 "Impulse": Newton restitution (9), Coulomb friction (10)–(11), sticking impulse
// (12), with the erratum signs and the energy guard described in collision_impulse.h.
#include "engine/dynamics/collision_impulse.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace rugosim {
namespace {

// Relative thresholds. A cone edge whose normal response K_nn ∓ μK_nt is below this fraction of
// its scale never meets the restitution line (the impulse along it would be unbounded), and a
// det K below this fraction of K_nn·K_tt is treated as singular.
constexpr double kEdgeTolerance = 1e-12;
constexpr double kSingularTolerance = 1e-12;
// ΔKE above this fraction of |J·u| counts as energy added; below it is rounding (for ε = 1, μ = 0
// the exact ΔKE is 0 and rounding leaves about 1e-16 of it).
constexpr double kEnergyTolerance = 1e-13;
// How far below the zero-energy restitution a clamped collision aims (relative to ε_eff).
constexpr double kRootMargin = 1e-9;

// K and u in the contact frame (n, t); impulses below are (J_n, J_t) in that frame.
struct ContactFrame {
  double knn = 0.0;
  double knt = 0.0;
  double ktt = 0.0;
  double det = 0.0;
  double un = 0.0;
  double ut = 0.0;
  double mu = 0.0;

  Vec2 response(const Vec2& j) const {  // K J in the frame
    return Vec2(knn * j.x() + knt * j.y(), knt * j.x() + ktt * j.y());
  }
  double energy_change(const Vec2& j) const { return j.dot(Vec2(un, ut) + 0.5 * response(j)); }
  // Slip after an impulse: u_t⁺ = u_t + (KJ)_t.
  double slip_after(const Vec2& j) const { return ut + knt * j.x() + ktt * j.y(); }
};

enum class Mode { kSticking, kSlidingPositive, kSlidingNegative, kFrictionless };

// An impulse that depends affinely on x = 1 + ε within one mode: j(x) = value, dj/dx = slope.
struct Candidate {
  Vec2 value;
  Vec2 slope;
};

// Cone edge J = J_n (1, −μ s) scaled for x = 1; its impulse at x is x times this. The edge meets
// the restitution line (K J)_n = x·|u_n| only when K_nn − μ s K_nt > 0.
bool cone_edge(const ContactFrame& f, double s, Vec2& unit_edge) {
  const double den = f.knn - f.mu * s * f.knt;
  if (!(den > kEdgeTolerance * (f.knn + f.mu * std::abs(f.knt)))) return false;
  const double jn = -f.un / den;
  unit_edge = Vec2(jn, -f.mu * s * jn);
  return true;
}

// The Coulomb mode at x = 1 + ε: slide on an edge when even that edge leaves a slip of the sign
// its friction opposes; otherwise the sticking impulse lies inside the cone.
Mode choose_mode(const ContactFrame& f, double x) {
  Vec2 edge;
  if (cone_edge(f, 1.0, edge) && f.slip_after(x * edge) > 0.0) return Mode::kSlidingPositive;
  if (cone_edge(f, -1.0, edge) && f.slip_after(x * edge) < 0.0) return Mode::kSlidingNegative;
  if (f.det > kSingularTolerance * f.knn * f.ktt) return Mode::kSticking;
  return Mode::kFrictionless;
}

Candidate candidate(const ContactFrame& f, Mode mode, double x) {
  const double q = -f.un;  // > 0
  Vec2 edge;
  switch (mode) {
    case Mode::kSlidingPositive:
      cone_edge(f, 1.0, edge);
      return {x * edge, edge};
    case Mode::kSlidingNegative:
      cone_edge(f, -1.0, edge);
      return {x * edge, edge};
    case Mode::kSticking: {
      // Solve (KJ)_n = x q, (KJ)_t = −u_t by Cramer's rule.
      const double jt = -(f.knn * f.ut + f.knt * x * q) / f.det;
      const double djt = -f.knt * q / f.det;
      const double jn = (x * q - f.knt * jt) / f.knn;
      const double djn = (q - f.knt * djt) / f.knn;
      return {Vec2(jn, jt), Vec2(djn, djt)};
    }
    case Mode::kFrictionless:
      break;
  }
  return {Vec2(x * q / f.knn, 0.0), Vec2(q / f.knn, 0.0)};
}

// Values of x in (1, x_top) where the mode can switch: the edge slips cross zero there.
int mode_switches(const ContactFrame& f, double x_top, std::array<double, 2>& out) {
  int count = 0;
  for (const double s : {1.0, -1.0}) {
    Vec2 edge;
    if (!cone_edge(f, s, edge)) continue;
    const double rate = f.knt * edge.x() + f.ktt * edge.y();  // d u_t⁺ / dx along the edge
    if (rate == 0.0) continue;
    const double x = -f.ut / rate;
    if (x > 1.0 && x < x_top) out[static_cast<std::size_t>(count++)] = x;
  }
  if (count == 2 && out[0] < out[1]) std::swap(out[0], out[1]);
  return count;
}

// Largest x in [1, x_top] with ΔKE(x) ≤ 0, walking the pieces down from x_top. On each piece
// ΔKE(x_h + h) = e0 + e1 h + ½ e2 h² is a convex quadratic; the root below x_h is taken in the
// cancellation-free form h = −2 e0 / (e1 + √(e1² − 2 e2 e0)).
double energy_safe_x(const ContactFrame& f, double x_top) {
  std::array<double, 2> switches{};
  const int count = mode_switches(f, x_top, switches);
  double x_high = x_top;
  for (int piece = 0; piece <= count; ++piece) {
    const double x_low = piece < count ? switches[static_cast<std::size_t>(piece)] : 1.0;
    const Mode mode = choose_mode(f, 0.5 * (x_low + x_high));
    const Candidate c = candidate(f, mode, x_high);
    const double e0 = f.energy_change(c.value);
    if (e0 <= 0.0) return x_high;
    const double e1 = c.slope.dot(Vec2(f.un, f.ut) + f.response(c.value));
    const double e2 = c.slope.dot(f.response(c.slope));
    const double disc = e1 * e1 - 2.0 * e2 * e0;
    if (e1 > 0.0 && disc >= 0.0) {
      const double x = x_high - 2.0 * e0 / (e1 + std::sqrt(disc));
      if (x >= x_low) return std::max(x, 1.0);
    }
    x_high = x_low;
  }
  return 1.0;  // ε = 0 dissipates in every mode (see the header)
}

// K in the (n, t) frame, from the bodies' terms rather than by projecting K: with
// perp(r)·n = cross(r, n) and perp(r)·t = r·n every entry is a sum of products without
// cancellation, and det K = s² + s(α|r_a|² + β|r_b|²) + αβ·cross(r_a, r_b)² (s = 1/m_a + 1/m_b,
// α = 1/I_a, β = 1/I_b) is a sum of non-negative terms, so a nearly singular K is measured to
// full relative precision instead of drowning in the rounding of K_nn·K_tt − K_nt².
ContactFrame contact_frame(const ContactBodyState& a, const ContactBodyState& b, const Vec2& n) {
  const double s = a.inverse_mass + b.inverse_mass;
  const double an = cross(a.arm, n);
  const double at = a.arm.dot(n);
  const double bn = cross(b.arm, n);
  const double bt = b.arm.dot(n);
  const double ia = a.inverse_inertia;
  const double ib = b.inverse_inertia;
  const double c = cross(a.arm, b.arm);
  ContactFrame f;
  f.knn = s + ia * an * an + ib * bn * bn;
  f.knt = ia * an * at + ib * bn * bt;
  f.ktt = s + ia * at * at + ib * bt * bt;
  f.det = s * s + s * (ia * a.arm.squaredNorm() + ib * b.arm.squaredNorm()) + ia * ib * c * c;
  return f;
}

void check_inputs(const ContactBodyState& a, const ContactBodyState& b, const Vec2& normal,
                  double restitution, double friction) {
  for (const ContactBodyState* body : {&a, &b}) {
    if (!(body->inverse_mass >= 0.0) || !(body->inverse_inertia >= 0.0) ||
        !std::isfinite(body->inverse_mass) || !std::isfinite(body->inverse_inertia) ||
        !body->velocity.allFinite() || !std::isfinite(body->angular_velocity) ||
        !body->arm.allFinite()) {
      throw std::invalid_argument("collision_impulse: invalid body state");
    }
  }
  if (!normal.allFinite() || std::abs(normal.norm() - 1.0) > 1e-9) {
    throw std::invalid_argument("collision_impulse: the normal must be a unit vector");
  }
  if (!(restitution >= 0.0 && restitution <= 1.0)) {
    throw std::invalid_argument("collision_impulse: restitution must lie in [0, 1]");
  }
  if (!(friction >= 0.0) || !std::isfinite(friction)) {
    throw std::invalid_argument("collision_impulse: friction must be finite and >= 0");
  }
}

}  // namespace

Vec2 contact_point_velocity(const ContactBodyState& body) {
  return body.velocity + body.angular_velocity * perp(body.arm);
}

Vec2 relative_contact_velocity(const ContactBodyState& a, const ContactBodyState& b) {
  return contact_point_velocity(a) - contact_point_velocity(b);
}

Mat2 collision_matrix(const ContactBodyState& a, const ContactBodyState& b) {
  // Entry by entry, so that K is exactly symmetric.
  const Vec2 pa = perp(a.arm);
  const Vec2 pb = perp(b.arm);
  const double s = a.inverse_mass + b.inverse_mass;
  const double ia = a.inverse_inertia;
  const double ib = b.inverse_inertia;
  const double off = ia * pa.x() * pa.y() + ib * pb.x() * pb.y();
  Mat2 k;
  k << s + ia * pa.x() * pa.x() + ib * pb.x() * pb.x(), off,  //
      off, s + ia * pa.y() * pa.y() + ib * pb.y() * pb.y();
  return k;
}

double kinetic_energy_change(const Mat2& k, const Vec2& relative_velocity, const Vec2& impulse) {
  return impulse.dot(relative_velocity + 0.5 * (k * impulse));
}

ImpulseResult collision_impulse(const ContactBodyState& a, const ContactBodyState& b,
                                const Vec2& normal, double restitution, double friction) {
  check_inputs(a, b, normal, restitution, friction);
  const Vec2 n = normal;
  const Vec2 t = perp(n);
  const Mat2 k = collision_matrix(a, b);
  const Vec2 u = relative_contact_velocity(a, b);

  ImpulseResult result;
  result.vn = u.dot(n);
  result.vt = u.dot(t);
  result.restitution = restitution;

  ContactFrame f = contact_frame(a, b, n);
  f.un = result.vn;
  f.ut = result.vt;
  f.mu = friction;

  if (!(f.un < 0.0)) return result;  // separating or resting: not a collision
  if (!(f.knn > 0.0)) {
    result.degenerate = true;
    return result;
  }
  result.collision = true;

  const double x_top = 1.0 + restitution;
  double x = x_top;
  Vec2 j = candidate(f, choose_mode(f, x), x).value;
  if (f.energy_change(j) > kEnergyTolerance * std::abs(j.dot(Vec2(f.un, f.ut)))) {
    // The root is exact only up to rounding, which can leave ΔKE a hair above 0: aim a
    // relative kRootMargin below it, and bounce not at all if even that is not enough.
    x = 1.0 + (energy_safe_x(f, x_top) - 1.0) * (1.0 - kRootMargin);
    if (f.energy_change(candidate(f, choose_mode(f, x), x).value) > 0.0) x = 1.0;
    result.energy_clamped = true;
    result.restitution = x - 1.0;
  }
  const Mode mode = choose_mode(f, x);
  j = candidate(f, mode, x).value;

  result.sticking = mode == Mode::kSticking;
  result.jn = j.x();
  result.jt = j.y();
  result.impulse = j.x() * n + j.y() * t;
  result.energy_change = kinetic_energy_change(k, u, result.impulse);
  return result;
}

void apply_impulse(const Vec2& impulse, ContactBodyState& a, ContactBodyState& b) {
  a.velocity += a.inverse_mass * impulse;
  a.angular_velocity += a.inverse_inertia * cross(a.arm, impulse);
  b.velocity -= b.inverse_mass * impulse;
  b.angular_velocity -= b.inverse_inertia * cross(b.arm, impulse);
}

}  // namespace rugosim
