// AOBB tree construction and tree-versus-tree descent (paper §3.1, §3.2).
#include "engine/collision/aobb_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "engine/collision/obb_overlap.h"
#include "engine/geometry/multiresolution.h"

namespace rugosim {

namespace {

// Every box is grown by this share of its coordinates' magnitude: projections, corners and
// placements round at about 1e-16 of the coordinates, and without the pad a segment point, or
// a child's corner, could land a rounding error outside its box. A box that misses a contact
// by a rounding error misses it all the same.
constexpr double kRoundingPad = 1e-12;

Obb padded(const Obb& box) {
  const double scale =
      box.center.cwiseAbs().maxCoeff() + box.half_extents.x() + box.half_extents.y();
  return box.fattened(kRoundingPad * scale);
}

// Major principal axis of regularly spaced samples on a segment (t = 0, ..., 1).
Vec2 segment_axis(const CubicSegment& segment) {
  std::array<Vec2, AobbTree::kAxisSamples> samples;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] = segment.point(static_cast<double>(i) / static_cast<double>(samples.size() - 1));
  }
  return principal_axes(samples).major;
}

// Box of a node that no wavelet level orients (odd counts, or above the coarsest level). The
// principal axes of the children's corners fit poorly (two half-discs side by side look
// square to the covariance at any angle: a circle's root came out 1.7 times the area of its
// bounding square), so the node takes the smallest-area box around its children's corners.
// By the rotating-calipers theorem that box has a side along an edge of the corners' convex
// hull; trying each hull edge, and the principal axes, finds it.
Obb smallest_box(std::span<const Vec2, 8> corners) {
  std::array<Vec2, 8> sorted;
  std::copy(corners.begin(), corners.end(), sorted.begin());
  std::sort(sorted.begin(), sorted.end(), [](const Vec2& p, const Vec2& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  // Andrew's monotone chain: lower hull then upper hull, counter-clockwise.
  std::array<Vec2, 16> hull;
  std::size_t size = 0;
  auto add = [&](const Vec2& p, std::size_t floor) {
    while (size >= floor + 2 && cross(hull[size - 1] - hull[size - 2], p - hull[size - 2]) <= 0.0)
      --size;
    hull[size++] = p;
  };
  for (const Vec2& p : sorted)
    add(p, 0);
  const std::size_t lower = size - 1;
  for (std::size_t i = sorted.size() - 1; i-- > 0;)
    add(sorted[i], lower);
  Obb best = bound_along(corners, principal_axes(corners).major);
  for (std::size_t i = 0; i + 1 < size; ++i) {
    const Vec2 edge = hull[i + 1] - hull[i];
    const double length = edge.norm();
    if (!(length > 0.0)) continue;
    const Obb candidate = bound_along(corners, edge / length);
    if (candidate.area() < best.area()) best = candidate;
  }
  return best;
}

// Half-perimeter: which box of a pair to split first (the larger one, as in OBBTree).
double box_size(const Obb& box) {
  return box.half_extents.x() + box.half_extents.y();
}

struct BuildNode {
  Obb box;
  std::uint32_t left = AobbTree::kNone;
  std::uint32_t right = AobbTree::kNone;
  std::uint32_t segment = AobbTree::kNone;
};

}  // namespace

namespace {

// Leaves in segment order, then each level's parents, bottom-up; returns the root's index.
std::uint32_t build_bottom_up(const PeriodicBSpline& curve, const ToleranceProfile& tolerances,
                              double min_margin, std::vector<BuildNode>& build) {
  const std::size_t n = curve.size();
  build.reserve(2 * n);
  std::vector<std::uint32_t> level;
  level.reserve(n);
  for (std::size_t j = 0; j < n; ++j) {
    const CubicSegment& segment = curve.segment(j);
    // Axes from samples, extents from the Bezier polygon: the convex hull property makes the
    // box contain the whole segment, not just the samples.
    const Obb fitted = bound_along(segment.bezier(), segment_axis(segment));
    BuildNode leaf;
    leaf.box = padded(fitted.fattened(std::max(tolerances.segment_range(j).hi, min_margin)));
    leaf.segment = static_cast<std::uint32_t>(j);
    level.push_back(static_cast<std::uint32_t>(build.size()));
    build.push_back(leaf);
  }

  const Multiresolution resolution(curve.control_points());
  std::vector<std::uint32_t> next;
  next.reserve(n / 2 + 1);
  for (int k = 1; level.size() > 1; ++k) {
    // Wavelet level k exists only while every count so far was even, so its coarse segment i
    // covers exactly the fine segments of this level's node i.
    std::optional<PeriodicBSpline> coarse;
    if (k <= resolution.level_count() && resolution.control_points(k).size() == level.size() / 2) {
      coarse.emplace(resolution.control_points(k));
    }
    next.clear();
    for (std::size_t i = 0; i + 1 < level.size(); i += 2) {
      std::array<Vec2, 8> corners;
      const auto first = build[level[i]].box.corners();
      const auto second = build[level[i + 1]].box.corners();
      std::copy(first.begin(), first.end(), corners.begin());
      std::copy(second.begin(), second.end(), corners.begin() + 4);
      BuildNode parent;
      parent.box = padded(coarse ? bound_along(corners, segment_axis(coarse->segment(i / 2)))
                                 : smallest_box(corners));
      parent.left = level[i];
      parent.right = level[i + 1];
      next.push_back(static_cast<std::uint32_t>(build.size()));
      build.push_back(parent);
    }
    // An odd node out goes up unchanged: its range [i·2^k, n) still follows the pattern.
    if (level.size() % 2 == 1) next.push_back(level.back());
    level.swap(next);
  }
  return level.front();
}

}  // namespace

AobbTree::AobbTree(const PeriodicBSpline& curve, const ToleranceProfile& tolerances,
                   double min_margin) {
  const std::size_t n = curve.size();
  if (tolerances.size() != n) {
    throw std::invalid_argument("AobbTree: " + std::to_string(tolerances.size()) +
                                " tolerances for " + std::to_string(n) + " segments");
  }
  std::vector<BuildNode> build;
  const std::uint32_t root = build_bottom_up(curve, tolerances, min_margin, build);

  // Lay the nodes out depth-first (first child next to its parent) for the query's descent.
  struct Pending {
    std::uint32_t build_index;
    std::uint32_t parent;  // node whose `right` is this one; kNone for a first child or root
    int depth;
  };
  nodes_.reserve(build.size());
  leaf_node_.assign(n, kNone);
  std::vector<Pending> stack;
  stack.reserve(2 * static_cast<std::size_t>(kMaxDepth) + 2);
  stack.push_back({root, kNone, 0});
  while (!stack.empty()) {
    const Pending p = stack.back();
    stack.pop_back();
    const BuildNode& b = build[p.build_index];
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    if (p.parent != kNone) nodes_[p.parent].right = index;
    Node node;
    node.box = b.box;
    node.segment = b.segment;
    nodes_.push_back(node);
    depth_ = std::max(depth_, p.depth);
    if (b.left == kNone) {
      leaf_node_[b.segment] = index;
    } else {
      stack.push_back({b.right, index, p.depth + 1});
      stack.push_back({b.left, kNone, p.depth + 1});
    }
  }
  if (depth_ > kMaxDepth) throw std::length_error("AobbTree: tree too deep for the query stack");
  for (const std::uint32_t leaf : leaf_node_) {
    for (const Vec2& corner : nodes_[leaf].box.corners())
      reach_ = std::max(reach_, corner.norm());
  }
}

void AobbTree::query(const AobbTree& other, const Transform2& other_to_this,
                     std::vector<LeafPair>& out, double slack) const {
  // Depth-first: at most one pending sibling per level of either tree waits at a time, so the
  // fixed stack cannot overflow. Entries hold indices only (no member initialisers), so the
  // stack costs nothing to set up; the other node's box is placed when its pair is tested.
  struct Pending {
    std::uint32_t a;
    std::uint32_t b;
  };
  std::array<Pending, 2 * static_cast<std::size_t>(kMaxDepth) + 2> stack;
  std::size_t top = 0;
  stack[top++] = {0, 0};
  while (top > 0) {
    const Pending p = stack[--top];
    const Node& na = nodes_[p.a];
    const Node& nb = other.nodes_[p.b];
    const Obb b_box = nb.box.transformed(other_to_this);
    if (!obb_overlap(na.box, b_box, slack)) continue;
    if (na.is_leaf() && nb.is_leaf()) {
      out.push_back({na.segment, nb.segment});
    } else if (!na.is_leaf() && (nb.is_leaf() || box_size(na.box) >= box_size(nb.box))) {
      stack[top++] = {na.right, p.b};
      stack[top++] = {p.a + 1, p.b};
    } else {
      stack[top++] = {p.a, nb.right};
      stack[top++] = {p.a, p.b + 1};
    }
  }
}

}  // namespace rugosim
