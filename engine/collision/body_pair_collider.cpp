#include "engine/collision/body_pair_collider.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "engine/collision/obb_overlap.h"
#include "engine/collision/segment_distance.h"

namespace rugosim {

namespace {

// Whether segments i and j of a closed curve with n segments are the same or neighbours.
bool same_or_adjacent(std::size_t i, std::size_t j, std::size_t n) {
  return i == j || (i + 1) % n == j || (j + 1) % n == i;
}

bool duplicates(const Contact& c, const Contact& kept, std::size_t na, std::size_t nb) {
  if (!same_or_adjacent(c.segment_a, kept.segment_a, na) ||
      !same_or_adjacent(c.segment_b, kept.segment_b, nb)) {
    return false;
  }
  // The same place, within the contact band (or rounding, when there is no band): around a
  // joint both neighbouring leaf pairs find it.
  const double radius = std::max(c.lambda_a + c.lambda_b, kept.lambda_a + kept.lambda_b) +
                        1e-12 * (1.0 + c.point.norm());
  return (c.point_a - kept.point_a).norm() <= radius && (c.point_b - kept.point_b).norm() <= radius;
}

// Whether a minimum that a leaf pair found at an end of its segment (t = 0 or 1) is only the
// edge of that pair's parameter square and not a minimum of the whole curves: the distance
// still falls when the parameter moves on across the joint. The neighbouring pair, which is
// even closer and so inside the band too, reports the real minimum. d(½‖a − b‖²)/dt_a = d·a'
// and d(½‖a − b‖²)/dt_b = −d·b', with d = a − b; all in the frame the segments are given in.
bool falls_past_a_joint(const CubicSegment& seg_a, double t_a, const CubicSegment& seg_b,
                        double t_b, const Vec2& d) {
  auto falls = [&](const Vec2& derivative, double t, double sign) {
    if (t > 0.0 && t < 1.0) return false;
    const double slope = sign * d.dot(derivative);  // rate of change of ½‖d‖² as t grows
    const double margin = 1e-9 * d.norm() * derivative.norm();
    // At t = 1 the curve continues for growing t, at t = 0 for shrinking t.
    return t >= 1.0 ? slope < -margin : slope > margin;
  };
  return falls(seg_a.derivative(t_a), t_a, 1.0) || falls(seg_b.derivative(t_b), t_b, -1.0);
}

// m: how far any point within `reach` of B's origin has moved relative to A between the
// placements `from` and `to` of B's frame in A's: ‖R₁ − R₀‖·reach + ‖t₁ − t₀‖, with
// ‖R₁ − R₀‖ = √(Δcos² + Δsin²) for plane rotations.
double relative_motion(const Transform2& from, const Transform2& to, double reach) {
  const double dc = to.cos_angle() - from.cos_angle();
  const double ds = to.sin_angle() - from.sin_angle();
  return std::sqrt(dc * dc + ds * ds) * reach + (to.translation() - from.translation()).norm();
}

}  // namespace

void merge_duplicate_contacts(std::vector<Contact>& contacts, std::size_t segments_a,
                              std::size_t segments_b) {
  auto closer_first = [](const Contact& p, const Contact& q) {
    if (p.distance != q.distance) return p.distance < q.distance;
    if (p.segment_a != q.segment_a) return p.segment_a < q.segment_a;
    if (p.segment_b != q.segment_b) return p.segment_b < q.segment_b;
    return p.t_a < q.t_a || (p.t_a == q.t_a && p.t_b < q.t_b);
  };
  std::sort(contacts.begin(), contacts.end(), closer_first);
  std::vector<Contact> kept;
  kept.reserve(contacts.size());
  for (const Contact& c : contacts) {
    const bool seen = std::any_of(kept.begin(), kept.end(), [&](const Contact& k) {
      return duplicates(c, k, segments_a, segments_b);
    });
    if (!seen) kept.push_back(c);
  }
  std::sort(kept.begin(), kept.end(), [](const Contact& p, const Contact& q) {
    if (p.segment_a != q.segment_a) return p.segment_a < q.segment_a;
    if (p.t_a != q.t_a) return p.t_a < q.t_a;
    if (p.segment_b != q.segment_b) return p.segment_b < q.segment_b;
    return p.t_b < q.t_b;
  });
  contacts = std::move(kept);
}

void BodyPairCollider::find_leaf_pairs(const CollisionShape& a, const CollisionShape& b,
                                       const Transform2& b_to_a, LeafPairCache* cache,
                                       double min_margin) {
  leaf_pairs_.clear();
  leaf_apart_.clear();
  if (cache == nullptr) {
    a.tree().query(b.tree(), b_to_a, leaf_pairs_);
    return;
  }
  if (cache->a != a.id() || cache->b != b.id() ||
      relative_motion(cache->b_to_a, b_to_a, b.tree().reach()) > cache->margin) {
    cache->a = cache->b = 0;  // until the query is through
    cache->b_to_a = b_to_a;
    const double smaller = std::min(a.tree().reach(), b.tree().reach());
    cache->margin = std::min(std::max(min_margin, LeafPairCache::kMarginRelative * smaller),
                             LeafPairCache::kMarginRelativeMax * smaller);
    cache->candidates.clear();
    // A little wider than the margin: boxes placed with other roundings than the query's must
    // still be among the candidates at a move of exactly the margin.
    const double slack = cache->margin * (1.0 + 1e-9) +
                         64.0 * std::numeric_limits<double>::epsilon() *
                             (a.tree().reach() + b.tree().reach() + b_to_a.translation().norm());
    a.tree().query(b.tree(), b_to_a, cache->candidates, slack);
    cache->apart.assign(cache->candidates.size(), LeafPairCache::Apart{});
    cache->a = a.id();
    cache->b = b.id();
  }
  // The query's own test at the leaves, in its order; each of B's boxes is placed once.
  b_leaf_boxes_.resize(b.curve().size());
  b_leaf_placed_.assign(b.curve().size(), 0);
  for (std::size_t k = 0; k < cache->candidates.size(); ++k) {
    const LeafPair& pair = cache->candidates[k];
    if (b_leaf_placed_[pair.segment_b] == 0) {
      b_leaf_boxes_[pair.segment_b] = b.tree().leaf_box(pair.segment_b).transformed(b_to_a);
      b_leaf_placed_[pair.segment_b] = 1;
    }
    if (obb_overlap(a.tree().leaf_box(pair.segment_a), b_leaf_boxes_[pair.segment_b])) {
      leaf_pairs_.push_back(pair);
      leaf_apart_.push_back(&cache->apart[k]);
    }
  }
}

void BodyPairCollider::collide(const CollisionShape& a, const Transform2& place_a,
                               const CollisionShape& b, const Transform2& place_b,
                               ContactManifold& out, LeafPairCache* cache, double min_margin) {
  out.intersections.clear();
  out.contacts.clear();
  candidates_.clear();

  // Work in A's frame: A's segments are used as stored, only B's are moved.
  const Transform2 b_to_a = place_a.inverse() * place_b;
  find_leaf_pairs(a, b, b_to_a, cache, min_margin);
  // m: how far the bodies may reach into each other and still only touch (touching.h).
  const double smaller_reach = std::min(a.tree().reach(), b.tree().reach());
  const double touching_depth = kTouchingDepthRelative * smaller_reach;
  // m: how deep a nearest point on the other curve's inner side is read as inside (touching.h).
  const double dipped_depth = kDippedDepthRelative * smaller_reach;

  for (std::size_t k = 0; k < leaf_pairs_.size(); ++k) {
    const LeafPair& pair = leaf_pairs_[k];
    LeafPairCache::Apart* apart = leaf_apart_.empty() ? nullptr : leaf_apart_[k];
    if (apart != nullptr && apart->margin > 0.0 &&
        relative_motion(apart->b_to_a, b_to_a, b.tree().reach()) < apart->margin) {
      continue;  // still apart (see LeafPairCache::Apart)
    }
    const CubicSegment& seg_a = a.curve().segment(pair.segment_a);
    const CubicSegment seg_b = b.curve().segment(pair.segment_b).transformed(b_to_a);
    // No contact of this pair can have a wider band than this: farther apart, it is separated,
    // and proving that is much cheaper than finding the nearest points exactly.
    const double widest_band = a.segment_band(pair.segment_a) + b.segment_band(pair.segment_b);
    const WithinThreshold within = nearest_points_within(seg_a, seg_b, widest_band, settings_);
    const double zero = within.crossing_distance;
    if (apart != nullptr) {
      // Apart means beyond the band and beyond "touching" (crossing_distance), which a pair
      // without rugosity and a coarse accuracy can have wider than its band.
      const double margin = within.lower_bound - std::max(widest_band, zero);
      *apart = {b_to_a, margin > 0.0 ? margin : 0.0};
    }
    if (!within.nearest) continue;  // separated
    const NearestPoints& near = *within.nearest;
    // Within crossing_distance, reaching into each other by less than the touching depth, or
    // with one curve's nearest point plainly inside the other by at most dipped_depth and the
    // band (dipped_inside), the pair touches or crosses (touching.h): touching is a contact at
    // distance zero, along the normal that clears it.
    std::optional<Touch> touch;
    if (near.distance <= zero ||
        (near.distance <= touching_depth + zero && seen_from_inside(near, seg_a, seg_b)) ||
        (near.distance <= std::min(widest_band, dipped_depth) &&
         dipped_inside(near, seg_a, seg_b))) {
      touch = touching(near, seg_a, seg_b, touching_depth, settings_);
      if (!touch) {
        out.intersections.push_back({pair.segment_a, pair.segment_b, near.t_a, near.t_b,
                                     place_a.apply(0.5 * (near.point_a + near.point_b))});
        continue;
      }
    }
    // A touch acts where the curves reach deepest into each other (touching.h).
    const double t_a = touch ? touch->t_a : near.t_a;
    const double t_b = touch ? touch->t_b : near.t_b;
    const double lambda_a = a.tolerances().at(pair.segment_a, t_a);
    const double lambda_b = b.tolerances().at(pair.segment_b, t_b);
    const double band = std::max(lambda_a + lambda_b, a.min_band() + b.min_band());
    if (near.distance > band) continue;  // separated
    // (Touching pairs have no direction between their points to tell; the duplicates found
    // around a joint are merged below.)
    if (!touch &&
        falls_past_a_joint(seg_a, near.t_a, seg_b, near.t_b, near.point_a - near.point_b)) {
      continue;  // the neighbouring pair holds the real minimum
    }

    Contact c;
    c.segment_a = pair.segment_a;
    c.segment_b = pair.segment_b;
    c.t_a = t_a;
    c.t_b = t_b;
    c.lambda_a = lambda_a;
    c.lambda_b = lambda_b;
    c.point_a = place_a.apply(touch ? seg_a.point(t_a) : near.point_a);
    c.point_b = place_a.apply(touch ? seg_b.point(t_b) : near.point_b);
    c.distance = touch ? 0.0 : near.distance;
    // The paper's contact point, corrected: the midpoint of the nearest points (DESIGN.md).
    const Vec2 d = c.point_a - c.point_b;
    c.point = c.point_b + 0.5 * d;
    // At nearest points d is normal to B wherever B is smooth, and it points from B to A by
    // construction; only when the curves touch (d ~ 0) does B's own normal decide.
    const double negligible = 1e-12 * (1.0 + c.point.norm());
    Vec2 normal = touch                   ? Vec2(place_a.rotate(touch->normal))
                  : d.norm() > negligible ? Vec2(d / d.norm())
                                          : Vec2(place_a.rotate(outward_normal(seg_b, near.t_b)));
    if (!(normal.norm() > 0.5)) normal = Vec2::UnitY();  // a segment shrunk to a point
    c.normal = normal;
    candidates_.push_back(c);
  }
  merge_duplicate_contacts(candidates_, a.curve().size(), b.curve().size());
  out.contacts = candidates_;
}

}  // namespace rugosim
