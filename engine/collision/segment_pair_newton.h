// Local descent for the nearest points of two cubic segments (paper §3.2, eq. 4): Newton's
// method on f(s, t) = ‖a(s) − b(t)‖² over a parameter rectangle, with the bounds handled as an
// active set, so that minima on an edge or at a corner are reached too (there eq. 4 has no
// root: the gradient points out of the rectangle).
//
// Why not plain Newton on eq. 4: its roots include maxima and saddles, and at an edge minimum
// it has none. Here each step must lower f (backtracking along the projected step), so the
// descent only ever stops at a local minimum of the rectangle. Where the Hessian of f is not
// positive definite the step falls back to Gauss-Newton with Levenberg damping, whose matrix
// JᵀJ ignores the curvature terms and always gives a descent direction. Near a crossing
// (f → 0) both steps are Newton's method on eq. 3, H(s, t) = a(s) − b(t) = 0.
//
// This only finds *a* local minimum; segment_distance.cpp proves or refutes that it is global.
#pragma once

#include "engine/geometry/cubic_segment.h"

namespace rugosim {

// A parameter rectangle [s0, s1] x [t0, t1] inside [0, 1]².
struct ParameterBox {
  double s0 = 0.0, s1 = 1.0;
  double t0 = 0.0, t1 = 1.0;
};

struct LocalMinimum {
  double s = 0.0;
  double t = 0.0;
  double distance2 = 0.0;  // m², ‖a(s) − b(t)‖²
};

// Descends from (s, t), clamped into the box, until no step lowers f, f falls to stop_distance2
// or below, or max_iterations steps were taken. Always finite for finite segments.
LocalMinimum descend_to_local_minimum(const CubicSegment& a, const CubicSegment& b,
                                      const ParameterBox& box, double s, double t,
                                      double stop_distance2, int max_iterations);

}  // namespace rugosim
