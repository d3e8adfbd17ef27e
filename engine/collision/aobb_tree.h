// The augmented oriented bounding box tree (AOBB tree) of one body (paper §3.1), and the
// tree-versus-tree descent that finds the pairs of segments close enough for the narrow phase
// (§3.2).
//
// Leaves: one elementary box per segment, with the principal axes of samples on the segment,
// extents from its Bezier control points (so the box surely contains the segment, which
// samples alone would not promise), fattened by the segment's tolerance band.
//
// Deviation from the paper: the paper fattens segment j's box by λ_j, but the tolerance along
// the boundary is the interpolated λ_j(t) (§4.1), which can exceed λ_j inside the segment (the
// interpolating cubic overshoots near a jump of λ). A contact inside the band must never be
// missed, so the box is fattened by max over t of λ_j(t) instead.
//
// Inner nodes: built bottom-up by pairing adjacent nodes (segments 2i and 2i+1, then pairs of
// pairs, ...), so the node j of tree level k covers segments [j·2^k, (j+1)·2^k). When a level
// has an odd count its last node is carried up unchanged to the next level (a binary tree with
// depth ceil(log2 n)). A level-k box takes its orientation from the coarse curve of wavelet
// level k (coarse segment j covers the same fine segments) where that level exists; elsewhere
// (odd counts, or above the coarsest level) the node is the smallest-area box around its
// children's corners (the principal axes of those corners fit poorly; see aobb_tree.cpp).
// Extents always come from projecting all the children's corners, so a parent contains its
// children's boxes whatever its orientation.
//
// Trees live in the body frame and are built once; a moving body never rebuilds its tree.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/core/transform.h"
#include "engine/geometry/obb.h"
#include "engine/geometry/periodic_bspline.h"
#include "engine/geometry/tolerance_profile.h"

namespace rugosim {

// Two segments whose leaf boxes overlap: a candidate for the narrow phase.
struct LeafPair {
  std::uint32_t segment_a = 0;  // segment of the tree that was queried
  std::uint32_t segment_b = 0;  // segment of the other tree
  friend bool operator==(const LeafPair&, const LeafPair&) = default;
  friend auto operator<=>(const LeafPair&, const LeafPair&) = default;
};

class AobbTree {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  // Points sampled on a segment (fine or coarse) to fit a box's axes.
  static constexpr std::size_t kAxisSamples = 16;
  // Deepest tree that the query's fixed stack can descend (n up to 2^40 segments).
  static constexpr int kMaxDepth = 40;

  // Nodes are stored in depth-first order: an inner node's first child is the next node.
  struct Node {
    Obb box;                        // body frame, contains the tolerance band of its segments
    std::uint32_t right = kNone;    // index of the second child; kNone for a leaf
    std::uint32_t segment = kNone;  // the leaf's segment; kNone for an inner node
    bool is_leaf() const { return right == kNone; }
  };

  // Throws std::invalid_argument when the profile's size differs from the curve's.
  // Leaves are fattened by the segment's largest tolerance, and at least by min_margin (m).
  AobbTree(const PeriodicBSpline& curve, const ToleranceProfile& tolerances,
           double min_margin = 0.0);

  std::size_t segment_count() const { return leaf_node_.size(); }
  std::size_t node_count() const { return nodes_.size(); }
  // Edges on the longest path from the root to a leaf: ceil(log2 n).
  int depth() const { return depth_; }

  const std::vector<Node>& nodes() const { return nodes_; }
  const Node& node(std::size_t i) const { return nodes_[i]; }
  const Node& root() const { return nodes_.front(); }
  // Index of the first child of inner node i.
  std::uint32_t left_child(std::size_t i) const { return static_cast<std::uint32_t>(i + 1); }
  const Obb& leaf_box(std::size_t segment) const { return nodes_[leaf_node_[segment]].box; }
  std::uint32_t leaf_node(std::size_t segment) const { return leaf_node_[segment]; }

  // Appends to `out` every pair (segment of this tree, segment of `other`) whose leaf boxes
  // overlap once the other tree is placed in this tree's frame by `other_to_this` (that is
  // inverse(X_this) * X_other, computed once per body pair). The result is exactly the set an
  // all-pairs test of the leaf boxes gives, in depth-first order. Allocates nothing except
  // when `out` grows. With a slack (m) boxes count as overlapping when they come within about
  // that distance (obb_overlap.h): the pairs that may overlap once the trees have moved
  // relative to each other by at most `slack`; the order of the pairs without slack is kept
  // within that longer list.
  void query(const AobbTree& other, const Transform2& other_to_this, std::vector<LeafPair>& out,
             double slack = 0.0) const;

  // m: the largest distance of any leaf box corner from the body frame's origin; no point of
  // the boundary or its band is farther out.
  double reach() const { return reach_; }

 private:
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> leaf_node_;  // segment -> node index
  int depth_ = 0;
  double reach_ = 0.0;  // m
};

}  // namespace rugosim
