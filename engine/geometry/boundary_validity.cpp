#include "engine/geometry/boundary_validity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/geometry/mass_properties.h"

namespace rugosim {
namespace {

// --- Exact orientation predicate -------------------------------------------------------------
// A floating-point filter (Shewchuk's bound for the straightforward determinant) decides almost
// every call; only near-collinear triples pay for the exact sum. Exact as long as products of
// coordinates neither overflow nor underflow (|coordinates| roughly in [1e-140, 1e140]).

// s + e = a + b exactly (Knuth).
void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double b_virtual = s - a;
  const double a_virtual = s - b_virtual;
  e = (a - a_virtual) + (b - b_virtual);
}

// p + e = a·b exactly: fma rounds once, so it returns the rounding error of the product.
void two_product(double a, double b, double& p, double& e) {
  p = a * b;
  e = std::fma(a, b, -p);
}

// Sign of the exact sum of the terms: grow a non-overlapping expansion one term at a time
// (Shewchuk's Grow-Expansion); its most significant non-zero component carries the sign.
template <std::size_t N>
int exact_sign_of_sum(const std::array<double, N>& terms) {
  std::array<double, N> expansion{};
  std::size_t length = 0;
  for (double term : terms) {
    double carry = term;
    for (std::size_t i = 0; i < length; ++i) {
      double low = 0.0;
      two_sum(carry, expansion[i], carry, low);
      expansion[i] = low;
    }
    expansion[length++] = carry;
  }
  for (std::size_t i = length; i-- > 0;) {
    if (expansion[i] > 0.0) return 1;
    if (expansion[i] < 0.0) return -1;
  }
  return 0;
}

// Sign of a − b, exactly.
int compare(double a, double b) {
  return (a > b) - (a < b);
}

// For r collinear with p and q: whether r lies on the closed segment pq.
bool within(const Vec2& p, const Vec2& q, const Vec2& r) {
  return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
         std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
}

// Whether every point lies on one line (or all coincide): the curve then runs back and forth
// along it, which is better reported as enclosing no area than as touching itself.
bool all_collinear(const std::vector<Vec2>& points) {
  const Vec2& first = points.front();
  const auto other =
      std::find_if(points.begin(), points.end(), [&](const Vec2& p) { return p != first; });
  if (other == points.end()) return true;
  return std::all_of(points.begin(), points.end(),
                     [&](const Vec2& p) { return orientation_sign(first, *other, p) == 0; });
}

// --- Edge pairs -------------------------------------------------------------------------------

enum class Contact { kNone, kCross, kTouch };

struct EdgeHit {
  Contact kind = Contact::kNone;
  Vec2 at = Vec2::Zero();
};

EdgeHit intersect(const Vec2& p1, const Vec2& p2, const Vec2& q1, const Vec2& q2) {
  const int o1 = orientation_sign(p1, p2, q1);
  const int o2 = orientation_sign(p1, p2, q2);
  const int o3 = orientation_sign(q1, q2, p1);
  const int o4 = orientation_sign(q1, q2, p2);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    const Vec2 d = p2 - p1;
    const Vec2 e = q2 - q1;
    const double s = std::clamp(cross(q1 - p1, e) / cross(d, e), 0.0, 1.0);
    return {Contact::kCross, p1 + s * d};
  }
  // Touching: an endpoint of one edge on the other (this covers collinear overlap too).
  if (o1 == 0 && within(p1, p2, q1)) return {Contact::kTouch, q1};
  if (o2 == 0 && within(p1, p2, q2)) return {Contact::kTouch, q2};
  if (o3 == 0 && within(q1, q2, p1)) return {Contact::kTouch, p1};
  if (o4 == 0 && within(q1, q2, p2)) return {Contact::kTouch, p2};
  return {};
}

// Consecutive edges a→b, b→c fold back when c lies on the ray from b through a.
bool folds_back(const Vec2& a, const Vec2& b, const Vec2& c) {
  if (orientation_sign(a, b, c) != 0) return false;
  return compare(a.x(), b.x()) == compare(c.x(), b.x()) &&
         compare(a.y(), b.y()) == compare(c.y(), b.y());
}

// --- Flattening -------------------------------------------------------------------------------

// Closed polyline: edge i runs from vertex[i] to vertex[(i + 1) % m] and lies on segment[i].
struct Polyline {
  std::vector<Vec2> vertex;
  std::vector<std::size_t> segment;
};

std::size_t pieces_for(const CubicSegment& s, double tolerance) {
  // |f''| is convex along the segment (f'' is linear), so its maximum is at an end.
  const double curvature =
      std::max(s.second_derivative(0.0).norm(), s.second_derivative(1.0).norm());
  const double needed = std::ceil(std::sqrt(curvature / (8.0 * tolerance)));
  if (!(needed < static_cast<double>(kMaxPiecesPerSegment))) return kMaxPiecesPerSegment;
  return std::max<std::size_t>(1, static_cast<std::size_t>(needed));
}

Polyline flatten(const PeriodicBSpline& curve, double tolerance) {
  Polyline line;
  for (std::size_t j = 0; j < curve.size(); ++j) {
    const CubicSegment& s = curve.segment(j);
    const std::size_t k = pieces_for(s, tolerance);
    // Each segment contributes its start and interior points; its end is the next segment's
    // start, evaluated once, so neighbouring edges share bitwise-equal vertices.
    for (std::size_t i = 0; i < k; ++i) {
      const Vec2 v = s.point(static_cast<double>(i) / static_cast<double>(k));
      // A repeated vertex (a segment collapsed to a point) would make a zero-length edge
      // whose neighbours touch without being consecutive.
      if (!line.vertex.empty() && v == line.vertex.back()) continue;
      line.vertex.push_back(v);
      line.segment.push_back(j);
    }
  }
  while (line.vertex.size() > 1 && line.vertex.back() == line.vertex.front()) {
    line.vertex.pop_back();
    line.segment.pop_back();
  }
  return line;
}

// --- Reports ----------------------------------------------------------------------------------

// How two pieces of the boundary meet, in the words of the reason string.
struct Meeting {
  const char* pair;  // "segments 3 and 11 <pair>"
  const char* self;  // "segment 3 <self>"
};
constexpr Meeting kCrossing{"cross", "crosses itself"};
constexpr Meeting kTouching{"touch", "touches itself"};
constexpr Meeting kFolding{"fold back onto each other", "folds back onto itself"};

ValidityReport crossing_report(std::size_t seg_a, std::size_t seg_b, const Vec2& at,
                               const Meeting& meeting) {
  ValidityReport r;
  r.valid = false;
  r.issue = BoundaryIssue::kSelfCrossing;
  r.segment_a = std::min(seg_a, seg_b);
  r.segment_b = std::max(seg_a, seg_b);
  r.where = at;
  std::ostringstream message;
  if (r.segment_a == r.segment_b) {
    message << "segment " << r.segment_a << ' ' << meeting.self;
  } else {
    message << "segments " << r.segment_a << " and " << r.segment_b << ' ' << meeting.pair;
  }
  message << " near (" << at.x() << ", " << at.y() << ")";
  r.reason = message.str();
  return r;
}

// --- Search -----------------------------------------------------------------------------------
// The edges, in curve order, are grouped into a binary tree of boxes (the idea of the paper's
// tree of boxes, §3.1, with axis-aligned boxes). Each node also keeps the cone of its edge
// directions: when the directions of a run of edges span less than a half turn, the run is
// monotone along the cone's bisector, so no two of its edges can meet. That prunes the
// self-test of smooth stretches and the test between neighbouring stretches, which boxes alone
// never can (neighbours' boxes always share a vertex); what is left is mostly boxes of distant
// stretches that overlap. On smooth curves this costs O(m log m); a plain sort-and-sweep on x
// intervals was several times slower on jagged curves, whose short edges overlap in x by the
// dozen.

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Widths from here up count as turning: the margin covers the rounding of atan2 and of the
// sums below, so a run called monotone surely is.
constexpr double kMonotoneWidth = std::numbers::pi - 1e-9;
constexpr std::size_t kLeafEdges = 8;

// The arc of directions [start, start + width] (rad) of a run of edges.
struct Cone {
  double start = 0.0;
  double width = 0.0;
  bool monotone() const { return width < kMonotoneWidth; }
};

// The shorter arc that covers both arcs (one of the two that start where an input starts).
Cone merge(const Cone& p, const Cone& q) {
  if (!p.monotone() || !q.monotone()) return {0.0, kTwoPi};
  const auto ahead = [](double from, double to) {  // angle from `from` to `to`, in [0, 2π)
    const double d = to - from;
    return d < 0.0 ? d + kTwoPi : d;
  };
  const double from_p = std::max(p.width, ahead(p.start, q.start) + q.width);
  const double from_q = std::max(q.width, ahead(q.start, p.start) + p.width);
  return from_p <= from_q ? Cone{p.start, from_p} : Cone{q.start, from_q};
}

struct Node {
  Aabb box;
  Cone cone;
  std::size_t lo = 0, hi = 0;  // edges [lo, hi)
  std::size_t left = 0, right = 0;
  bool leaf = true;
};

class CrossingSearch {
 public:
  explicit CrossingSearch(const Polyline& line) : line_(line), m_(line.vertex.size()) {
    angle_.reserve(m_);
    for (std::size_t i = 0; i < m_; ++i) {
      const Vec2 d = vertex(i + 1) - vertex(i);
      angle_.push_back(std::atan2(d.y(), d.x()));
    }
    nodes_.reserve(2 * (m_ / kLeafEdges + 1));
    root_ = build(0, m_);
  }

  // The first crossing in a fixed traversal order, or a valid report.
  ValidityReport run() {
    self(root_);
    return found_;
  }

 private:
  const Vec2& vertex(std::size_t i) const { return line_.vertex[i % m_]; }

  std::size_t build(std::size_t lo, std::size_t hi) {
    Node node;
    node.lo = lo;
    node.hi = hi;
    if (hi - lo <= kLeafEdges) {
      node.cone = {angle_[lo], 0.0};
      for (std::size_t i = lo; i < hi; ++i) {
        node.box.extend(vertex(i));
        node.cone = merge(node.cone, {angle_[i], 0.0});
      }
      node.box.extend(vertex(hi));
    } else {
      const std::size_t mid = lo + (hi - lo) / 2;
      node.leaf = false;
      node.left = build(lo, mid);
      node.right = build(mid, hi);
      node.box = nodes_[node.left].box;
      node.box.extend(nodes_[node.right].box);
      node.cone = merge(nodes_[node.left].cone, nodes_[node.right].cone);
    }
    nodes_.push_back(node);
    return nodes_.size() - 1;
  }

  bool found() const { return !found_.valid; }

  // Edges i and j share a vertex.
  bool consecutive(std::size_t i, std::size_t j) const {
    return (i + 1) % m_ == j || (j + 1) % m_ == i;
  }

  // Runs that follow each other around the closed curve.
  bool adjacent(const Node& a, const Node& b) const {
    return a.hi == b.lo || b.hi == a.lo || (a.hi == m_ && b.lo == 0) || (b.hi == m_ && a.lo == 0);
  }

  void self(std::size_t n) {
    const Node& node = nodes_[n];
    if (found() || node.cone.monotone()) return;
    if (node.leaf) {
      for (std::size_t i = node.lo; i < node.hi; ++i) {
        for (std::size_t j = i + 2; j < node.hi; ++j)
          test_edges(i, j);
      }
      return;
    }
    self(node.left);
    self(node.right);
    pair(node.left, node.right);
  }

  void pair(std::size_t a, std::size_t b) {
    const Node& x = nodes_[a];
    const Node& y = nodes_[b];
    if (found() || !x.box.overlaps(y.box)) return;
    if (adjacent(x, y) && merge(x.cone, y.cone).monotone()) return;
    if (x.leaf && y.leaf) {
      for (std::size_t i = x.lo; i < x.hi; ++i) {
        for (std::size_t j = y.lo; j < y.hi; ++j)
          test_edges(i, j);
      }
    } else if (y.leaf || (!x.leaf && x.hi - x.lo >= y.hi - y.lo)) {
      pair(x.left, b);
      pair(x.right, b);
    } else {
      pair(a, y.left);
      pair(a, y.right);
    }
  }

  void test_edges(std::size_t i, std::size_t j) {
    if (found() || consecutive(i, j)) return;
    const Vec2& p1 = vertex(i);
    const Vec2& p2 = vertex(i + 1);
    const Vec2& q1 = vertex(j);
    const Vec2& q2 = vertex(j + 1);
    for (int axis = 0; axis < 2; ++axis) {
      if (std::max(p1[axis], p2[axis]) < std::min(q1[axis], q2[axis]) ||
          std::max(q1[axis], q2[axis]) < std::min(p1[axis], p2[axis])) {
        return;
      }
    }
    const EdgeHit hit = intersect(p1, p2, q1, q2);
    if (hit.kind == Contact::kNone) return;
    found_ = crossing_report(line_.segment[i], line_.segment[j], hit.at,
                             hit.kind == Contact::kCross ? kCrossing : kTouching);
  }

  const Polyline& line_;
  std::size_t m_;
  std::vector<double> angle_;  // rad, direction of each edge
  std::vector<Node> nodes_;
  std::size_t root_ = 0;
  ValidityReport found_;
};

// A report on the first thing that is not finite, or a valid one.
ValidityReport finiteness(const PeriodicBSpline& curve, const Aabb& hull) {
  for (std::size_t j = 0; j < curve.size(); ++j) {
    const CubicSegment& s = curve.segment(j);
    const bool finite = std::all_of(s.power().begin(), s.power().end(),
                                    [](const Vec2& a) { return a.allFinite(); });
    if (finite && s.hull_bounds().extent().allFinite()) continue;
    ValidityReport r;
    r.valid = false;
    r.issue = BoundaryIssue::kNonFinite;
    r.segment_a = r.segment_b = j;
    r.reason = "segment " + std::to_string(j) + " is not finite (its coordinates overflow)";
    return r;
  }
  // Far below overflow, but products of coordinates (areas, orientation tests) must not overflow.
  constexpr double kMaxCoordinate = 1e150;
  if (!(hull.min.cwiseAbs().maxCoeff() < kMaxCoordinate &&
        hull.max.cwiseAbs().maxCoeff() < kMaxCoordinate)) {
    ValidityReport r;
    r.valid = false;
    r.issue = BoundaryIssue::kNonFinite;
    r.reason = "the boundary reaches beyond 1e150 m, where products of coordinates overflow";
    return r;
  }
  return {};
}

}  // namespace

int orientation_sign(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  // (3 + 16ε)ε with ε = 2⁻⁵³ bounds the error of det relative to |left| + |right|.
  const double bound = 3.3306690738754716e-16 * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  // det = ax·by − ax·cy − cx·by − ay·bx + ay·cx + cy·bx, each product split exactly in two.
  const std::array<std::array<double, 2>, 6> products{{{a.x(), b.y()},
                                                       {-a.x(), c.y()},
                                                       {-c.x(), b.y()},
                                                       {-a.y(), b.x()},
                                                       {a.y(), c.x()},
                                                       {c.y(), b.x()}}};
  std::array<double, 12> terms{};
  for (std::size_t i = 0; i < products.size(); ++i)
    two_product(products[i][0], products[i][1], terms[2 * i], terms[2 * i + 1]);
  return exact_sign_of_sum(terms);
}

ValidityReport check_boundary(const PeriodicBSpline& curve) {
  const Aabb hull = curve.hull_bounds();
  if (ValidityReport r = finiteness(curve, hull); !r.valid) return r;

  const double diagonal = hull.diagonal();
  const auto no_area = [](const std::string& why) {
    ValidityReport r;
    r.valid = false;
    r.issue = BoundaryIssue::kZeroArea;
    r.reason = "the boundary encloses no area: " + why;
    return r;
  };
  if (!(diagonal > 0.0) || all_collinear(curve.control_points())) {
    return no_area("its control points all lie on one line");
  }

  // Crossings first: a symmetric figure-eight also has zero signed area, and the crossing,
  // with its segments and point, is the more useful thing to say about it.
  const Polyline line = flatten(curve, kBoundaryRelativeTolerance * diagonal);
  const std::size_t m = line.vertex.size();
  for (std::size_t i = 0; i < m && m >= 3; ++i) {
    const std::size_t next = (i + 1) % m;
    const Vec2& b = line.vertex[next];
    if (folds_back(line.vertex[i], b, line.vertex[(i + 2) % m])) {
      return crossing_report(line.segment[i], line.segment[next], b, kFolding);
    }
  }
  if (m >= 3) {
    ValidityReport crossing = CrossingSearch(line).run();
    if (!crossing.valid) return crossing;
  }

  const double area = signed_area(curve);
  if (m < 3 || !(std::abs(area) > kMinRelativeArea * diagonal * diagonal)) {
    std::ostringstream why;
    why << "|A| = " << std::abs(area) << " m² is at most " << kMinRelativeArea
        << " of its hull diagonal (" << diagonal << " m) squared";
    return no_area(why.str());
  }
  return {};
}

}  // namespace rugosim
