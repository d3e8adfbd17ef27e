#include "engine/collision/segment_pair_newton.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rugosim {
namespace {

// Levenberg damping of the Gauss-Newton matrix, relative to its diagonal: small enough to keep
// the convergence rate, large enough that straight parallel segments (JᵀJ singular) get a
// finite step.
constexpr double kDamping = 1e-8;
constexpr int kMaxHalvings = 16;
constexpr double kTiny = 1e-300;
// Relative change of f within rounding.
constexpr double kLevel = 8.0 * std::numeric_limits<double>::epsilon();

struct Step {
  double ds = 0.0;
  double dt = 0.0;
  bool valid = false;
  bool newton = false;  // a Newton step on a positive definite Hessian
};

// The Newton step on the free variables (those not held at a bound by a gradient pointing out
// of the box); Gauss-Newton with damping where the Hessian is not positive definite.
Step descent_step(const CubicSegment& a, const CubicSegment& b, const ParameterBox& box, double s,
                  double t, const Vec2& r) {
  const Vec2 da = a.derivative(s);
  const Vec2 db = b.derivative(t);
  // Half the gradient of f = ‖r‖², r = a(s) − b(t).
  const double gs = r.dot(da);
  const double gt = -r.dot(db);
  const bool free_s = !((s <= box.s0 && gs > 0.0) || (s >= box.s1 && gs < 0.0));
  const bool free_t = !((t <= box.t0 && gt > 0.0) || (t >= box.t1 && gt < 0.0));
  const double jss = da.squaredNorm();
  const double jtt = db.squaredNorm();
  const double jst = -da.dot(db);
  Step step;
  if (free_s && free_t) {
    const double hss = jss + r.dot(a.second_derivative(s));
    const double htt = jtt - r.dot(b.second_derivative(t));
    const double det = hss * htt - jst * jst;
    if (hss > 0.0 && htt > 0.0 && det > 1e-14 * hss * htt) {
      step = {(-gs * htt + jst * gt) / det, (-gt * hss + jst * gs) / det, true, true};
    } else {
      const double mss = jss * (1.0 + kDamping) + kDamping * jtt;
      const double mtt = jtt * (1.0 + kDamping) + kDamping * jss;
      const double mdet = mss * mtt - jst * jst;
      if (mdet > 0.0) {
        step = {(-gs * mtt + jst * gt) / mdet, (-gt * mss + jst * gs) / mdet, true, false};
      }
    }
  } else if (free_s) {
    const double hss = jss + r.dot(a.second_derivative(s));
    const double h = hss > 0.0 ? hss : jss * (1.0 + kDamping);
    if (h > 0.0) step = {-gs / h, 0.0, true, hss > 0.0};
  } else if (free_t) {
    const double htt = jtt - r.dot(b.second_derivative(t));
    const double h = htt > 0.0 ? htt : jtt * (1.0 + kDamping);
    if (h > 0.0) step = {0.0, -gt / h, true, htt > 0.0};
  }
  // No first-order decrease: a stationary point of the free variables.
  if (step.valid && !(-(gs * step.ds + gt * step.dt) > 0.0)) step.valid = false;
  return step;
}

}  // namespace

LocalMinimum descend_to_local_minimum(const CubicSegment& a, const CubicSegment& b,
                                      const ParameterBox& box, double s, double t,
                                      double stop_distance2, int max_iterations) {
  s = std::clamp(s, box.s0, box.s1);
  t = std::clamp(t, box.t0, box.t1);
  Vec2 r = a.point(s) - b.point(t);
  double f = r.squaredNorm();
  for (int iteration = 0; iteration < max_iterations && f > stop_distance2; ++iteration) {
    Step step = descent_step(a, b, box, s, t, r);
    if (!step.valid) break;
    // A step longer than the box only ends up clamped: shorten it so that backtracking starts
    // at a sensible length (damped Gauss-Newton steps can be huge along a valley).
    const double reach = std::max(std::abs(step.ds) / (box.s1 - box.s0 + kTiny),
                                  std::abs(step.dt) / (box.t1 - box.t0 + kTiny));
    if (reach > 1.0) {
      step.ds /= reach;
      step.dt /= reach;
      step.newton = false;
    }
    // Backtrack along the projected step until f drops: only ever descend. A full Newton
    // step is also taken when f stays level to rounding: near a minimum f is flat to about
    // √ε in the parameters, and only the root of the gradient (eq. 4) pins them down to ε,
    // which the certificate needs (its bound is first-order in the direction error).
    double alpha = 1.0;
    bool lowered = false;
    double ns = s, nt = t;
    Vec2 nr = r;
    for (int k = 0; k < kMaxHalvings; ++k, alpha *= 0.5) {
      ns = std::clamp(s + alpha * step.ds, box.s0, box.s1);
      nt = std::clamp(t + alpha * step.dt, box.t0, box.t1);
      nr = a.point(ns) - b.point(nt);
      const double nf = nr.squaredNorm();
      if (nf < f || (k == 0 && step.newton && nf <= f * (1.0 + kLevel))) {
        lowered = true;
        break;
      }
    }
    if (!lowered) break;
    const double moved = std::abs(ns - s) + std::abs(nt - t);
    s = ns;
    t = nt;
    r = nr;
    f = r.squaredNorm();
    if (moved <= 1e-15) break;
  }
  return {s, t, f};
}

}  // namespace rugosim
