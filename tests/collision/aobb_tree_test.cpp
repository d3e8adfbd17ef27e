#include "engine/collision/aobb_tree.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "engine/collision/obb_overlap.h"
#include "engine/core/random.h"
#include "engine/geometry/rugosity_pattern.h"
#include "engine/geometry/shapes.h"
#include "support/random_curves.h"

namespace rugosim {
namespace {

constexpr double kPi = std::numbers::pi;

struct Body {
  PeriodicBSpline curve;
  ToleranceProfile tolerances;
  AobbTree tree;
  double extent = 0.0;  // m, the control polygon's diagonal
};

// Kept out of line: inlined into random_body, GCC 12 reports a false null dereference in the
// vector it sizes.
[[gnu::noinline]] std::vector<Vec2> random_polygon(Rng& rng, std::size_t n) {
  return testing::random_control_polygon(rng, n);
}

// A random curve with random tolerances: one of the four rugosity patterns with a largest σ
// from 1e-4 to 3e-2 of the body's size, or no rugosity at all (bare Bezier hulls).
Body random_body(Rng& rng, std::size_t n) {
  auto points = random_polygon(rng, n);
  const double extent = testing::extent_of(points);
  const auto pattern = static_cast<RugosityPattern>(static_cast<int>(rng.uniform(0.0, 4.0)));
  const double sigma = rng.uniform() < 0.15 ? 0.0 : extent * std::pow(10.0, rng.uniform(-4, -1.5));
  const auto sigmas = pattern_sigmas(pattern, sigma, n, rng.next_u64());
  PeriodicBSpline curve(std::move(points));
  ToleranceProfile tolerances = ToleranceProfile::from_sigma(sigmas, 0.9);
  AobbTree tree(curve, tolerances);
  return Body{std::move(curve), std::move(tolerances), std::move(tree), extent};
}

// The same body scaled by k about the origin, tolerances included, with its own tree.
Body scaled(const Body& body, double k) {
  std::vector<Vec2> points = body.curve.control_points();
  for (Vec2& p : points)
    p *= k;
  std::vector<double> lambda = body.tolerances.segment_tolerances();
  for (double& l : lambda)
    l *= k;
  PeriodicBSpline curve(std::move(points));
  ToleranceProfile tolerances(std::move(lambda));
  AobbTree tree(curve, tolerances);
  return Body{std::move(curve), std::move(tolerances), std::move(tree), body.extent * k};
}

int ceil_log2(std::size_t n) {
  int d = 0;
  while ((std::size_t{1} << d) < n)
    ++d;
  return d;
}

// Every point of the tolerance band, f(t) ± λ_j(t)·normal, lies in segment j's leaf box.
TEST(AobbTree, LeafBoxesContainTheToleranceBand) {
  Rng rng(21);
  constexpr int kSamples = 201;
  for (int c = 0; c < 40; ++c) {
    const std::size_t n = testing::random_segment_count(rng, c);
    const Body body = random_body(rng, n);
    for (std::size_t j = 0; j < n; ++j) {
      const Obb& box = body.tree.leaf_box(j);
      for (int i = 0; i < kSamples; ++i) {
        const double t = static_cast<double>(i) / (kSamples - 1);
        const Vec2 p = body.curve.point(j, t);
        const Vec2 tangent = body.curve.derivative(j, t);
        const double lambda = body.tolerances.at(j, t);
        // Where the tangent vanishes the band is a disc: try both axis directions.
        const std::array<Vec2, 2> normals =
            tangent.norm() > 0.0 ? std::array<Vec2, 2>{perp(tangent).normalized(), Vec2::Zero()}
                                 : std::array<Vec2, 2>{Vec2::UnitX(), Vec2::UnitY()};
        for (const Vec2& normal : normals) {
          for (double side : {-1.0, 0.0, 1.0}) {
            ASSERT_TRUE(box.contains(p + side * lambda * normal))
                << "case " << c << ", n " << n << ", segment " << j << ", t " << t;
          }
        }
      }
    }
  }
}

// The fattening margin is the largest interpolated tolerance: no sample exceeds it, and the
// samples come within sampling error of it.
TEST(AobbTree, SegmentMaxToleranceIsTheMaximumOfTheInterpolatedBand) {
  Rng rng(22);
  int exceeds_lambda_j = 0;
  for (int c = 0; c < 60; ++c) {
    const auto n = static_cast<std::size_t>(rng.uniform(4.0, 40.0));
    std::vector<double> lambda(n);
    for (double& l : lambda)
      l = rng.uniform() < 0.3 ? 0.0 : rng.uniform(0.0, 0.01);
    const ToleranceProfile profile(lambda);
    for (std::size_t j = 0; j < n; ++j) {
      const double max_lambda = profile.segment_range(j).hi;
      double sampled = 0.0;
      for (int i = 0; i <= 20000; ++i) {
        const double value = profile.at(j, i / 20000.0);
        EXPECT_LE(value, max_lambda * (1.0 + 1e-12)) << "n " << n << ", segment " << j;
        sampled = std::max(sampled, value);
      }
      EXPECT_NEAR(sampled, max_lambda, 1e-8) << "n " << n << ", segment " << j;
      EXPECT_GE(max_lambda, profile.segment_tolerance(j));
      if (max_lambda > profile.segment_tolerance(j) * (1.0 + 1e-6)) ++exceeds_lambda_j;
    }
  }
  // The case the deviation from the paper is for does occur.
  EXPECT_GT(exceeds_lambda_j, 0);
  const ToleranceProfile flat(std::vector<double>(5, 0.002));
  EXPECT_EQ(flat.segment_range(3).hi, 0.002);
}

// A parent holds its children's boxes; the leaves under a node are a contiguous run of
// segments; the tree has 2n - 1 nodes and depth ceil(log2 n).
TEST(AobbTree, ParentsContainChildrenAndStructureIsBinary) {
  Rng rng(23);
  for (int c = 0; c < 60; ++c) {
    const std::size_t n = c < 8 ? static_cast<std::size_t>(4 + c)  // 4..11, odd counts too
                                : testing::random_segment_count(rng, c - 8);
    const Body body = random_body(rng, n);
    const AobbTree& tree = body.tree;
    ASSERT_EQ(tree.segment_count(), n);
    ASSERT_EQ(tree.node_count(), 2 * n - 1);
    EXPECT_EQ(tree.depth(), ceil_log2(n)) << "n " << n;
    // Leaf segment ranges, computed bottom-up over the depth-first layout (children follow
    // their parent, so a reverse pass sees children first).
    std::vector<std::size_t> first(tree.node_count()), last(tree.node_count());
    std::vector<int> seen(n, 0);
    for (std::size_t i = tree.node_count(); i-- > 0;) {
      const AobbTree::Node& node = tree.node(i);
      if (node.is_leaf()) {
        ASSERT_LT(node.segment, n);
        ++seen[node.segment];
        EXPECT_EQ(tree.leaf_node(node.segment), i);
        first[i] = last[i] = node.segment;
        continue;
      }
      EXPECT_EQ(node.segment, AobbTree::kNone);
      const std::size_t l = tree.left_child(i), r = node.right;
      ASSERT_GT(r, l);
      ASSERT_LT(r, tree.node_count());
      EXPECT_EQ(last[l] + 1, first[r]);  // adjacent runs, left before right
      first[i] = first[l];
      last[i] = last[r];
      const double slack = 1e-12 * (node.box.center.norm() + node.box.half_extents.sum());
      for (std::size_t child : {l, r}) {
        for (const Vec2& corner : tree.node(child).box.corners()) {
          EXPECT_TRUE(node.box.contains(corner, slack)) << "n " << n << ", node " << i;
        }
      }
    }
    EXPECT_EQ(first[0], 0u);
    EXPECT_EQ(last[0], n - 1);
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
  }
}

TEST(AobbTree, SmallAndOddCounts) {
  for (std::size_t n : {4u, 5u, 6u, 7u, 9u, 12u, 33u, 1000u, 1024u, 1025u}) {
    const PeriodicBSpline curve(circle_control_points(1.0, n));
    const ToleranceProfile tolerances(std::vector<double>(n, 0.01));
    const AobbTree tree(curve, tolerances);
    EXPECT_EQ(tree.node_count(), 2 * n - 1);
    EXPECT_EQ(tree.depth(), ceil_log2(n)) << n;
    // The root holds the whole circle and its band, and not much more.
    for (int i = 0; i < 64; ++i) {
      const double a = 2.0 * kPi * i / 64.0;
      EXPECT_TRUE(tree.root().box.contains(1.01 * Vec2(std::cos(a), std::sin(a))));
    }
    // Parents contain their children's boxes, not just the curve, so the root is looser than
    // the circle's bounding square; but not absurdly (carried odd nodes make it about 2x).
    EXPECT_LT(tree.root().box.area(), 2.25 * 4.0 * 1.01 * 1.01);
    // The body against itself in place: every segment meets itself and its neighbours.
    std::vector<LeafPair> pairs;
    tree.query(tree, Transform2::identity(), pairs);
    for (std::uint32_t j = 0; j < n; ++j) {
      const auto next = static_cast<std::uint32_t>((j + 1) % n);
      EXPECT_NE(std::find(pairs.begin(), pairs.end(), LeafPair{j, j}), pairs.end());
      EXPECT_NE(std::find(pairs.begin(), pairs.end(), LeafPair{j, next}), pairs.end());
      EXPECT_NE(std::find(pairs.begin(), pairs.end(), LeafPair{next, j}), pairs.end());
    }
  }
  const PeriodicBSpline curve(circle_control_points(1.0, 8));
  EXPECT_THROW(AobbTree(curve, ToleranceProfile(std::vector<double>(7, 0.0))),
               std::invalid_argument);
}

// Places body B against body A: A anywhere, B with its polygon centre at a random distance
// from A's (from deep overlap to well apart) in a random direction and orientation. Returns
// B's frame in A's frame.
Transform2 random_relative_placement(Rng& rng, const Body& a, const Body& b, double reach) {
  const Vec2 centre_a = a.curve.hull_bounds().center();
  const Vec2 centre_b = b.curve.hull_bounds().center();
  const double angle = rng.uniform(-kPi, kPi);
  const double spin = rng.uniform() < 0.2 ? kPi / 4.0 : rng.uniform(-kPi, kPi);
  const double distance = reach * rng.uniform(0.0, 0.5 * (a.extent + b.extent));
  const Vec2 target = centre_a + distance * Vec2(std::cos(angle), std::sin(angle));
  const Transform2 rotation(spin, Vec2::Zero());
  return Transform2(spin, target - rotation.apply(centre_b));
}

std::vector<LeafPair> all_pairs(const Body& a, const Body& b, const Transform2& b_to_a) {
  std::vector<Obb> placed;
  for (std::size_t j = 0; j < b.tree.segment_count(); ++j)
    placed.push_back(b.tree.leaf_box(j).transformed(b_to_a));
  std::vector<LeafPair> out;
  for (std::uint32_t i = 0; i < a.tree.segment_count(); ++i) {
    for (std::uint32_t j = 0; j < placed.size(); ++j) {
      if (obb_overlap(a.tree.leaf_box(i), placed[j])) out.push_back({i, j});
    }
  }
  return out;
}

// The descent prunes nothing that matters: it returns exactly the leaf pairs whose boxes
// overlap, as testing all n_a·n_b leaf boxes does.
TEST(AobbTree, QueryEqualsAllPairsLeafTest) {
  Rng rng(24);
  int nonempty = 0, total_pairs = 0;
  for (int c = 0; c < 300; ++c) {
    // The first four cases pair the extremes 4 and 1024; the rest are log-uniform.
    const std::size_t na = testing::random_segment_count(rng, c < 4 ? c % 2 : 2);
    const std::size_t nb = testing::random_segment_count(rng, c < 4 ? c / 2 : 2);
    const Body a = random_body(rng, na);
    // Bodies of like size mostly, sometimes very different ones.
    Rng shape_rng(rng.next_u64());
    Body b = random_body(shape_rng, nb);
    if (rng.uniform() < 0.7) b = scaled(b, a.extent / b.extent * rng.uniform(0.2, 2.0));
    const Transform2 b_to_a = random_relative_placement(rng, a, b, 1.3);
    std::vector<LeafPair> found;
    a.tree.query(b.tree, b_to_a, found);
    std::vector<LeafPair> expected = all_pairs(a, b, b_to_a);
    std::sort(found.begin(), found.end());
    ASSERT_EQ(std::adjacent_find(found.begin(), found.end()), found.end()) << "duplicates";
    ASSERT_EQ(found, expected) << "case " << c << ", n_a " << na << ", n_b " << nb;
    nonempty += found.empty() ? 0 : 1;
    total_pairs += static_cast<int>(found.size());
  }
  EXPECT_GT(nonempty, 90);
  EXPECT_GT(total_pairs, 1500);
}

// With a slack the query finds every leaf pair that overlaps after B moved relative to A by at
// most that much (in translation and turn together), and keeps the exact pairs' order.
TEST(AobbTree, SlackQueryHoldsEveryPairAfterAMoveWithinTheSlack) {
  Rng rng(26);
  int moved_pairs = 0;
  for (int c = 0; c < 200; ++c) {
    const std::size_t na = testing::random_segment_count(rng, 2);
    const Body a = random_body(rng, na);
    Rng shape_rng(rng.next_u64());
    Body b = random_body(shape_rng, testing::random_segment_count(rng, 2));
    b = scaled(b, a.extent / b.extent * rng.uniform(0.3, 2.0));
    const Transform2 before = random_relative_placement(rng, a, b, 1.3);
    const double slack = 0.05 * a.extent * rng.uniform();
    std::vector<LeafPair> candidates;
    a.tree.query(b.tree, before, candidates, slack);
    // The exact pairs, in the query's own order, are the candidates that overlap exactly.
    std::vector<LeafPair> exact, filtered;
    a.tree.query(b.tree, before, exact);
    for (const LeafPair& p : candidates) {
      if (obb_overlap(a.tree.leaf_box(p.segment_a),
                      b.tree.leaf_box(p.segment_b).transformed(before))) {
        filtered.push_back(p);
      }
    }
    ASSERT_EQ(filtered, exact) << "case " << c;
    // Move B by at most the slack: a turn about its origin and a shift, sharing the budget.
    const double turn_share = rng.uniform();
    const double turn = turn_share * slack / b.tree.reach();
    const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
    const Vec2 shift = (1.0 - turn_share) * slack * Vec2(std::cos(angle), std::sin(angle));
    // Turning by φ moves a point at distance r by 2r·sin(φ/2) <= r·φ.
    const Transform2 after = Transform2(0.0, shift) * before * Transform2(turn, Vec2::Zero());
    std::vector<LeafPair> now;
    a.tree.query(b.tree, after, now);
    for (const LeafPair& p : now) {
      EXPECT_NE(std::find(candidates.begin(), candidates.end(), p), candidates.end())
          << "case " << c << ": a pair overlapping after the move was not a candidate";
    }
    moved_pairs += static_cast<int>(now.size());
  }
  EXPECT_GT(moved_pairs, 500);
}

// Closed segments [p, q] and [r, s] cross or touch.
bool edges_meet(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  const double d1 = cross(q - p, r - p), d2 = cross(q - p, s - p);
  const double d3 = cross(s - r, p - r), d4 = cross(s - r, q - r);
  return ((d1 >= 0 && d2 <= 0) || (d1 <= 0 && d2 >= 0)) &&
         ((d3 >= 0 && d4 <= 0) || (d3 <= 0 && d4 >= 0)) &&
         !(d1 == 0 && d2 == 0 && d3 == 0 && d4 == 0);  // collinear: leave to the band check
}

// A segment sampled as a polyline, with the tolerance at each sample.
struct SampledSegment {
  std::vector<Vec2> points;
  std::vector<double> lambda;
  Aabb band_bounds;  // the samples grown by the segment's largest tolerance
};

SampledSegment sample_segment(const Body& body, std::size_t j, const Transform2& x) {
  constexpr int kSamples = 200;
  SampledSegment out;
  for (int i = 0; i < kSamples; ++i) {
    const double t = static_cast<double>(i) / (kSamples - 1);
    out.points.push_back(x.apply(body.curve.point(j, t)));
    out.lambda.push_back(body.tolerances.at(j, t));
    out.band_bounds.extend(out.points.back());
  }
  const double grow = body.tolerances.segment_range(j).hi;
  out.band_bounds.min -= Vec2(grow, grow);
  out.band_bounds.max += Vec2(grow, grow);
  return out;
}

bool polylines_cross(const SampledSegment& a, const SampledSegment& b) {
  for (std::size_t s = 0; s + 1 < a.points.size(); ++s) {
    for (std::size_t u = 0; u + 1 < b.points.size(); ++u) {
      if (edges_meet(a.points[s], a.points[s + 1], b.points[u], b.points[u + 1])) return true;
    }
  }
  return false;
}

// Some samples p_a, p_b with ‖p_a − p_b‖ <= λ_a(t_a) + λ_b(t_b): a tolerated contact.
bool bands_meet(const SampledSegment& a, const SampledSegment& b) {
  for (std::size_t s = 0; s < a.points.size(); ++s) {
    for (std::size_t u = 0; u < b.points.size(); ++u) {
      if ((a.points[s] - b.points[u]).norm() <= a.lambda[s] + b.lambda[u]) return true;
    }
  }
  return false;
}

// Brute force on polylines (200 points per segment): every pair of segments that crosses, and
// every pair with samples within the sum of their tolerances, must come out of the tree query.
TEST(AobbTree, CrossingAndTouchingSegmentsAreReached) {
  Rng rng(25);
  int crossing_pairs = 0, band_pairs = 0;
  for (int c = 0; c < 30; ++c) {
    const auto na = static_cast<std::size_t>(rng.uniform(4.0, 70.0));
    const auto nb = static_cast<std::size_t>(rng.uniform(4.0, 70.0));
    const Body a = random_body(rng, na);
    Body b = random_body(rng, nb);
    b = scaled(b, a.extent / b.extent * rng.uniform(0.3, 1.5));
    const Transform2 b_to_a = random_relative_placement(rng, a, b, 0.8);
    std::vector<LeafPair> found;
    a.tree.query(b.tree, b_to_a, found);
    std::sort(found.begin(), found.end());

    std::vector<SampledSegment> sa, sb;
    for (std::size_t i = 0; i < na; ++i)
      sa.push_back(sample_segment(a, i, Transform2::identity()));
    for (std::size_t j = 0; j < nb; ++j)
      sb.push_back(sample_segment(b, j, b_to_a));
    for (std::uint32_t i = 0; i < na; ++i) {
      for (std::uint32_t j = 0; j < nb; ++j) {
        if (!sa[i].band_bounds.overlaps(sb[j].band_bounds)) continue;  // surely apart
        const bool crosses = polylines_cross(sa[i], sb[j]);
        const bool touches = crosses || bands_meet(sa[i], sb[j]);
        if (!touches) continue;
        crossing_pairs += crosses ? 1 : 0;
        band_pairs += crosses ? 0 : 1;
        EXPECT_TRUE(std::binary_search(found.begin(), found.end(), LeafPair{i, j}))
            << "case " << c << ": segments " << i << " and " << j << " are not reached";
      }
    }
  }
  // Both kinds occur: crossings, and contacts within the band that do not cross.
  EXPECT_GT(crossing_pairs, 50);
  EXPECT_GT(band_pairs, 50);
}

// Depth stays logarithmic over the sizes the engine uses.
TEST(AobbTree, DepthIsLogarithmic) {
  Rng rng(26);
  for (int c = 0; c < 30; ++c) {
    const std::size_t n = testing::random_segment_count(rng, c);
    const Body body = random_body(rng, n);
    EXPECT_EQ(body.tree.depth(), ceil_log2(n)) << n;
  }
}

}  // namespace
}  // namespace rugosim
