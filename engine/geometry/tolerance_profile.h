// Rugosity tolerances along a boundary (paper §2.2 and §4.1).
//
// Each segment j carries a roughness σ_j and a tolerance λ_j = q·σ_j (§2.2). Along the
// boundary the tolerance varies continuously: at parameter t of segment j it is the cubic
// through the four neighbouring λ's placed at the segments' midpoints (§4.1). For t < 1/2 the
// cubic runs through λ_{j-2..j+1} and is evaluated at t + 3/2; for t >= 1/2 it runs through
// λ_{j-1..j+2} at t + 1/2. The paper writes t + 1 in the second case, which jumps at t = 1/2;
// t + 1/2 is the value that makes λ(t) continuous (DESIGN.md, erratum). A cubic through a
// jump overshoots, so λ(t) is clamped at 0: a tolerance is never negative.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace rugosim {

struct ToleranceRange {
  double lo = 0.0;  // m
  double hi = 0.0;  // m
};

class ToleranceProfile {
 public:
  // λ_j = q·σ_j. Throws std::invalid_argument unless 0 < q <= 1 and every σ_j is finite and
  // >= 0, with at least one segment.
  static ToleranceProfile from_sigma(std::span<const double> sigma, double q);

  // Takes the per-segment tolerances λ_j directly (m, finite, >= 0).
  explicit ToleranceProfile(std::vector<double> segment_tolerances);

  std::size_t size() const { return lambda_.size(); }
  const std::vector<double>& segment_tolerances() const { return lambda_; }
  double segment_tolerance(std::size_t j) const { return lambda_[j]; }  // λ_j, m

  // True when every λ_j is equal: then λ(t) is that constant and `at` skips the cubic.
  bool homogeneous() const { return homogeneous_; }

  // λ_j(t), m: the continuous tolerance at parameter t in [0, 1] of segment j.
  double at(std::size_t j, double t) const;

  // Exact smallest and largest λ over the whole boundary (extrema of each cubic piece).
  ToleranceRange range() const;
  // Exact smallest and largest λ_j(t) over segment j: λ_j(t) can exceed λ_j near the joints,
  // which is what a box holding the segment's band must allow for.
  ToleranceRange segment_range(std::size_t j) const;

 private:
  // Range of cubic piece r (through λ_{r-1..r+2} at x = 0..3) over [x_lo, x_hi] ⊆ [1, 2].
  ToleranceRange piece_range(std::size_t r, double x_lo, double x_hi) const;

  std::vector<double> lambda_;
  bool homogeneous_ = true;
};

}  // namespace rugosim
