// Paper §3.2, eq. 4: the globally nearest points of two cubic segments. See the header for the
// method; this file holds the certificate and the branch and bound.
#include "engine/collision/segment_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

#include "engine/collision/bezier_bounds.h"
#include "engine/collision/circle_bound.h"
#include "engine/collision/segment_pair_newton.h"

namespace rugosim {
namespace {

// Inside a rectangle of the search the seed is already close, and the rectangle is split if
// the descent does not settle (at most the seed's iterations).
constexpr int kCellIterations = 6;
// Full descents from rectangles at the deepest level, at most, per search (a shallow
// seed_depth would otherwise pay one for every leftover rectangle).
constexpr int kMaxDeepDescents = 16;

struct Tolerances {
  double accuracy = 0.0;  // m
  double zero = 0.0;      // m
};

double coefficient_sum(const CubicSegment& c) {
  double sum = 0.0;
  for (const Vec2& k : c.power())
    sum += k.cwiseAbs().sum();
  return sum;
}

Tolerances tolerances(const CubicSegment& a, const CubicSegment& b,
                      const NarrowPhaseSettings& settings) {
  const double size = std::max(a.hull_bounds().diagonal(), b.hull_bounds().diagonal());
  const double magnitude = std::max(coefficient_sum(a), coefficient_sum(b));
  const double accuracy =
      settings.relative_accuracy * size + 64.0 * std::numeric_limits<double>::epsilon() * magnitude;
  return {accuracy, 4.0 * accuracy};
}

struct Candidate {
  double s = 0.0;
  double t = 0.0;
  double distance = std::numeric_limits<double>::infinity();
};

// The certificate of the header, step 3, on the rectangle `box`: a lower bound of the distance
// over it, from the local minimum m found in it. The slab first; when it falls short of
// `needed`, the circle (circle_bound.h), which holds where a convex piece rests in a concave one.
double certified_bound(const CubicSegment& a, const CubicSegment& b, const ParameterBox& box,
                       const LocalMinimum& m, double needed) {
  const Vec2 r = a.point(m.s) - b.point(m.t);
  const double d = r.norm();
  if (!(d > 0.0)) return 0.0;
  const double slab = separating_axis_bound(a, b, r / d, box.s0, box.s1, box.t0, box.t1);
  if (slab >= needed) return slab;
  return std::max(slab,
                  circle_separation_bound(a, b, m.s, m.t, box.s0, box.s1, box.t0, box.t1, needed));
}

struct Cell {
  double lower = 0.0;   // m, chord lower bound of the distance over the rectangle
  double chords = 0.0;  // m, distance between the chords: breaks ties among zero bounds
  ParameterBox box;
  BezierPolygon pa{};  // sub-polygons of a over [s0, s1] and b over [t0, t1]
  BezierPolygon pb{};
  double deviation_a = 0.0;  // m, chord deviations of pa and pb
  double deviation_b = 0.0;
  int depth = 0;
};

// Min-heap on the lower bound, the most promising rectangle first. Near a crossing many
// rectangles have a zero bound; those whose chords cross (or nearly) hold a root most likely.
bool farther(const Cell& x, const Cell& y) {
  if (x.lower != y.lower) return x.lower > y.lower;
  return x.chords > y.chords;
}

// Splits a rectangle in two or four. Only the parameter whose piece strays much further from
// its chord is halved: halving a straight piece tightens no bound, and a concave piece facing
// a straight one would otherwise breed a long row of rectangles along the straight one.
// The smallest bound of the children dropped goes to *dropped_min when given.
void push_children(const Cell& cell, double cutoff, std::vector<Cell>& heap,
                   double* dropped_min = nullptr) {
  const bool split_s = cell.deviation_a >= 0.25 * cell.deviation_b;
  const bool split_t = cell.deviation_b >= 0.25 * cell.deviation_a;
  std::array<BezierPolygon, 2> a_part{cell.pa, cell.pa}, b_part{cell.pb, cell.pb};
  std::array<double, 2> a_dev{cell.deviation_a, cell.deviation_a};
  std::array<double, 2> b_dev{cell.deviation_b, cell.deviation_b};
  std::array<double, 3> s_cut{cell.box.s0, cell.box.s1, cell.box.s1};
  std::array<double, 3> t_cut{cell.box.t0, cell.box.t1, cell.box.t1};
  if (split_s) {
    std::tie(a_part[0], a_part[1]) = split_in_half(cell.pa);
    a_dev = {chord_deviation(a_part[0]), chord_deviation(a_part[1])};
    s_cut[1] = 0.5 * (cell.box.s0 + cell.box.s1);
  }
  if (split_t) {
    std::tie(b_part[0], b_part[1]) = split_in_half(cell.pb);
    b_dev = {chord_deviation(b_part[0]), chord_deviation(b_part[1])};
    t_cut[1] = 0.5 * (cell.box.t0 + cell.box.t1);
  }
  for (std::size_t i = 0; i <= (split_s ? 1u : 0u); ++i) {
    for (std::size_t j = 0; j <= (split_t ? 1u : 0u); ++j) {
      Cell child;
      child.pa = a_part[i];
      child.pb = b_part[j];
      child.deviation_a = a_dev[i];
      child.deviation_b = b_dev[j];
      child.chords = closest_on_chords(child.pa[0], child.pa[3], child.pb[0], child.pb[3]).distance;
      child.lower = std::max(0.0, child.chords - a_dev[i] - b_dev[j]);
      if (child.lower >= cutoff) {
        if (dropped_min != nullptr) *dropped_min = std::min(*dropped_min, child.lower);
        continue;
      }
      child.box = {s_cut[i], s_cut[i + 1], t_cut[j], t_cut[j + 1]};
      child.depth = cell.depth + 1;
      heap.push_back(child);
      std::push_heap(heap.begin(), heap.end(), farther);
    }
  }
}

// The search's first rectangles, the four quarters of the square (those whose bound reaches
// `cutoff` are dropped; see push_children), on a fresh heap.
std::vector<Cell> first_cells(const CubicSegment& a, const CubicSegment& b, double cutoff,
                              double* dropped_min = nullptr) {
  std::vector<Cell> heap;
  heap.reserve(64);
  Cell root;
  root.pa = a.bezier();
  root.pb = b.bezier();
  root.deviation_a = chord_deviation(root.pa);
  root.deviation_b = chord_deviation(root.pb);
  push_children(root, cutoff, heap, dropped_min);
  return heap;
}

// Step 4 of the header: best-first search from `best`, which the certificate could not close.
Candidate branch_and_bound(const CubicSegment& a, const CubicSegment& b, const Tolerances& tol,
                           const NarrowPhaseSettings& settings, Candidate best) {
  const int cell_iterations = std::min(kCellIterations, settings.seed_iterations);
  int deep_descents = 0;
  std::vector<Cell> heap = first_cells(a, b, best.distance - tol.accuracy);
  for (int examined = 0; !heap.empty() && examined < settings.max_cells; ++examined) {
    std::pop_heap(heap.begin(), heap.end(), farther);
    const Cell cell = heap.back();
    heap.pop_back();
    if (cell.lower >= best.distance - tol.accuracy) break;  // so are all the others
    const ChordPair seed = closest_on_chords(cell.pa[0], cell.pa[3], cell.pb[0], cell.pb[3]);
    const ParameterBox& box = cell.box;
    const double s = box.s0 + seed.u * (box.s1 - box.s0);
    const double t = box.t0 + seed.v * (box.t1 - box.t0);
    // On small rectangles the chords' nearest points are already close to the rectangle's
    // minimum: try the certificate there before paying for a descent.
    const LocalMinimum at_seed{s, t, (a.point(s) - b.point(t)).squaredNorm()};
    const double d_seed = std::sqrt(at_seed.distance2);
    if (d_seed < best.distance) best = {s, t, d_seed};
    if (best.distance <= tol.zero) break;
    if (certified_bound(a, b, box, at_seed, best.distance - tol.accuracy) >=
        best.distance - tol.accuracy) {
      continue;
    }
    const LocalMinimum m =
        descend_to_local_minimum(a, b, box, s, t, tol.zero * tol.zero, cell_iterations);
    const double d = std::sqrt(m.distance2);
    if (d < best.distance) {
      // A new best: follow it out of the rectangle to its own minimum (or a crossing), so that
      // later rectangles are judged against the best value this basin can give.
      const LocalMinimum polished = descend_to_local_minimum(
          a, b, ParameterBox{}, m.s, m.t, tol.zero * tol.zero, settings.seed_iterations);
      best = {m.s, m.t, d};
      const double d_polished = std::sqrt(polished.distance2);
      if (d_polished < d) best = {polished.s, polished.t, d_polished};
    }
    if (best.distance <= tol.zero) break;
    if (certified_bound(a, b, box, m, best.distance - tol.accuracy) >=
        best.distance - tol.accuracy) {
      continue;
    }
    if (cell.depth < settings.max_depth) {
      push_children(cell, best.distance - tol.accuracy, heap);
      continue;
    }
    // As deep as the search may go: the rectangle's point seeds a full descent over the whole
    // square instead (a shallow search still finds crossings and minima that Newton can reach
    // from there, it only certifies less).
    if (++deep_descents > kMaxDeepDescents) continue;
    const LocalMinimum deep = descend_to_local_minimum(
        a, b, ParameterBox{}, m.s, m.t, tol.zero * tol.zero, settings.seed_iterations);
    const double d_deep = std::sqrt(deep.distance2);
    if (d_deep < best.distance) best = {deep.s, deep.t, d_deep};
    if (best.distance <= tol.zero) break;
  }
  return best;
}

// The decision form of step 4: a proof that every pair of points is farther apart than `level`,
// by the same bounds (a rectangle is dropped once its chord bound or its certificate exceeds the
// level). Its value is the smallest bound of the rectangles dropped, a lower bound of the
// distance above the level. Nothing as soon as a pair at most `level` apart turns up, or when
// the search runs out of depth or rectangles before it could prove it.
std::optional<double> proves_farther_than(const CubicSegment& a, const CubicSegment& b,
                                          const Tolerances& tol,
                                          const NarrowPhaseSettings& settings, double level) {
  const int cell_iterations = std::min(kCellIterations, settings.seed_iterations);
  // push_children drops children whose bound is at least its cutoff; here only those strictly
  // above the level may go.
  const double cutoff = std::nextafter(level, std::numeric_limits<double>::infinity());
  double lowest = std::numeric_limits<double>::infinity();
  std::vector<Cell> heap = first_cells(a, b, cutoff, &lowest);
  for (int examined = 0; !heap.empty(); ++examined) {
    if (examined >= settings.max_cells) return std::nullopt;
    std::pop_heap(heap.begin(), heap.end(), farther);
    const Cell cell = heap.back();
    heap.pop_back();
    const ChordPair seed = closest_on_chords(cell.pa[0], cell.pa[3], cell.pb[0], cell.pb[3]);
    const ParameterBox& box = cell.box;
    const double s = box.s0 + seed.u * (box.s1 - box.s0);
    const double t = box.t0 + seed.v * (box.t1 - box.t0);
    const LocalMinimum at_seed{s, t, (a.point(s) - b.point(t)).squaredNorm()};
    if (std::sqrt(at_seed.distance2) <= level) return std::nullopt;
    if (const double bound = certified_bound(a, b, box, at_seed, level); bound > level) {
      lowest = std::min(lowest, bound);
      continue;
    }
    const LocalMinimum m =
        descend_to_local_minimum(a, b, box, s, t, tol.zero * tol.zero, cell_iterations);
    if (std::sqrt(m.distance2) <= level) return std::nullopt;
    if (const double bound = certified_bound(a, b, box, m, level); bound > level) {
      lowest = std::min(lowest, bound);
      continue;
    }
    if (cell.depth >= settings.max_depth) return std::nullopt;
    push_children(cell, cutoff, heap, &lowest);
  }
  return lowest;
}
}  // namespace

double nearest_points_accuracy(const CubicSegment& a, const CubicSegment& b,
                               const NarrowPhaseSettings& settings) {
  return tolerances(a, b, settings).accuracy;
}

double crossing_distance(const CubicSegment& a, const CubicSegment& b,
                         const NarrowPhaseSettings& settings) {
  return tolerances(a, b, settings).zero;
}

WithinThreshold nearest_points_within(const CubicSegment& a, const CubicSegment& b,
                                      double threshold, const NarrowPhaseSettings& settings) {
  const Tolerances tol = tolerances(a, b, settings);
  const auto& pa = a.bezier();
  const auto& pb = b.bezier();
  const ParameterBox unit;
  // A proof of "farther than the threshold" must hold whatever the rounding of the distance a
  // full search would compute, so it clears the threshold by the accuracy; and touching pairs
  // (crossing_distance) are never proved apart. Bounds are reported less the accuracy, which
  // covers their own rounding.
  const double proof_level = std::max(threshold, tol.zero) + tol.accuracy;
  const bool may_prove = std::isfinite(threshold);
  WithinThreshold out;
  out.crossing_distance = tol.zero;
  // Whether m is the global minimum: touching, or a certificate within the accuracy of it.
  const auto settled = [&](const LocalMinimum& m) {
    const double d = std::sqrt(m.distance2);
    if (d <= tol.zero) return true;
    const double bound = certified_bound(a, b, unit, m, d - tol.accuracy);
    if (bound < d - tol.accuracy) return false;
    out.lower_bound = bound - tol.accuracy;
    return true;
  };
  const ChordPair seed = closest_on_chords(pa[0], pa[3], pb[0], pb[3]);
  // The cheapest proof: the chord bound of the whole square.
  if (may_prove) {
    const double chord_bound = seed.distance - chord_deviation(pa) - chord_deviation(pb);
    if (chord_bound > proof_level) {
      out.lower_bound = chord_bound - tol.accuracy;
      return out;
    }
  }
  LocalMinimum m = descend_to_local_minimum(a, b, unit, seed.u, seed.v, tol.zero * tol.zero,
                                            settings.seed_iterations);
  bool done = settled(m);
  if (!done) {
    // Second chance before the search: nearly parallel pieces (resting contact) whose first
    // descent ran to an end.
    if (const auto middle = middle_of_chord_overlap(pa[0], pa[3], pb[0], pb[3])) {
      const LocalMinimum m2 = descend_to_local_minimum(
          a, b, unit, middle->u, middle->v, tol.zero * tol.zero, settings.seed_iterations);
      if (m2.distance2 < m.distance2) {
        m = m2;
        done = settled(m);
      }
    }
  }
  Candidate best{m.s, m.t, std::sqrt(m.distance2)};
  if (!done) {
    // Proving that nothing comes within the threshold is far cheaper than pinning down the
    // minimum of a pair that is well apart (a concave piece facing a convex one): try it first.
    if (may_prove && best.distance > proof_level) {
      if (const std::optional<double> bound =
              proves_farther_than(a, b, tol, settings, proof_level)) {
        out.lower_bound = *bound - tol.accuracy;
        return out;
      }
    }
    best = branch_and_bound(a, b, tol, settings, best);
  }
  NearestPoints& nearest = out.nearest.emplace();
  nearest.t_a = best.s;
  nearest.t_b = best.t;
  nearest.point_a = a.point(best.s);
  nearest.point_b = b.point(best.t);
  nearest.distance = (nearest.point_a - nearest.point_b).norm();
  return out;
}

NearestPoints nearest_points(const CubicSegment& a, const CubicSegment& b,
                             const NarrowPhaseSettings& settings) {
  return *nearest_points_within(a, b, std::numeric_limits<double>::infinity(), settings).nearest;
}

}  // namespace rugosim
