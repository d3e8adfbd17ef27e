#include "engine/collision/body_pair_collider.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/collision/collision_pipeline.h"
#include "engine/core/random.h"
#include "engine/core/thread_pool.h"
#include "engine/geometry/orientation.h"
#include "engine/geometry/shapes.h"

namespace rugosim {
namespace {

CollisionShape make_shape(const std::vector<Vec2>& points, double sigma, double q = 0.9) {
  const Reversal ccw = make_counter_clockwise(points);
  return CollisionShape(PeriodicBSpline(ccw.control_points),
                        ToleranceProfile::from_sigma(std::vector<double>(points.size(), sigma), q));
}

// Floor: a 4 m x 0.4 m box whose top face is y = 0. Disk: radius 0.5 with 64 segments.
const CollisionShape& floor_shape() {
  static const CollisionShape shape = make_shape(box_control_points(4.0, 0.4, 48), 0.001 / 0.9);
  return shape;
}
const Transform2 kFloorPlace(0.0, Vec2(0.0, -0.2));

const CollisionShape& disk_shape() {
  static const CollisionShape shape = make_shape(circle_control_points(0.5, 64), 0.001 / 0.9);
  return shape;
}

TEST(BodyPairCollider, DiskWithinTheBandTouchesOnceWithTheFloorNormal) {
  // λ = 0.001 on both: the band is 0.002. The disk's lowest point is a knot (exactly radius
  // 0.5 below its centre) at angle −π/2, so a gap of 0.0015 is a tolerated contact.
  BodyPairCollider collider;
  ContactManifold m;
  for (double x : {-1.0, 0.0, 0.37}) {
    const Transform2 disk_place(0.0, Vec2(x, 0.5 + 0.0015));
    collider.collide(disk_shape(), disk_place, floor_shape(), kFloorPlace, m);
    ASSERT_EQ(m.state(), PairState::kContact) << x;
    ASSERT_EQ(m.contacts.size(), 1u) << "duplicates around the joint must be merged, x " << x;
    const Contact& c = m.contacts.front();
    EXPECT_NEAR(c.distance, 0.0015, 1e-9);
    EXPECT_NEAR(c.point.x(), x, 1e-6);
    EXPECT_NEAR(c.point.y(), 0.00075, 1e-9);  // midpoint of the nearest points
    EXPECT_NEAR(c.normal.x(), 0.0, 1e-9);
    EXPECT_NEAR(c.normal.y(), 1.0, 1e-12);  // normal of B (the floor) towards A (the disk)
    EXPECT_NEAR(c.lambda_a, 0.001, 1e-15);
    EXPECT_NEAR(c.lambda_b, 0.001, 1e-15);
    EXPECT_NEAR((c.point_a - c.point_b).norm(), c.distance, 1e-15);
  }
}

TEST(BodyPairCollider, NormalAlwaysPointsFromBTowardsA) {
  BodyPairCollider collider;
  ContactManifold m;
  const Transform2 disk_place(0.0, Vec2(0.2, 0.5 + 0.001));
  collider.collide(floor_shape(), kFloorPlace, disk_shape(), disk_place, m);
  ASSERT_EQ(m.state(), PairState::kContact);
  for (const Contact& c : m.contacts)
    EXPECT_NEAR(c.normal.y(), -1.0, 1e-9);  // disk -> floor
}

TEST(BodyPairCollider, BeyondTheBandIsSeparated) {
  BodyPairCollider collider;
  ContactManifold m;
  collider.collide(disk_shape(), Transform2(0.3, Vec2(0.0, 0.5 + 0.0021)), floor_shape(),
                   kFloorPlace, m);
  EXPECT_EQ(m.state(), PairState::kSeparated);
  EXPECT_TRUE(m.contacts.empty());
  EXPECT_TRUE(m.intersections.empty());
}

// A plank thinner than the band: the crate's bottom face lies on the inner side of the plank's
// bottom face, within the band, yet outside the plank. Only a dip of a millionth of the bodies'
// size is read as inside (kDippedDepthRelative), so the crate rests on the plank.
TEST(BodyPairCollider, ACrateOnAPlankThinnerThanTheBandIsInContact) {
  BodyPairCollider collider;
  ContactManifold m;
  const CollisionShape plank = make_shape(box_control_points(1.0, 0.001, 16), 0.003 / 0.9);
  const CollisionShape crate = make_shape(box_control_points(0.2, 0.1, 16), 0.003 / 0.9);
  for (const double gap : {0.0005, 0.002}) {
    collider.collide(crate, Transform2(0.0, Vec2(0.1, 0.0005 + gap + 0.05)), plank,
                     Transform2(0.0, Vec2::Zero()), m);
    EXPECT_EQ(m.state(), PairState::kContact) << gap;
    EXPECT_TRUE(m.intersections.empty()) << gap;
  }
}

TEST(BodyPairCollider, SunkenDiskIntersectsWhereTheCirclesCrossTheFace) {
  BodyPairCollider collider;
  ContactManifold m;
  const double sink = 0.01;
  collider.collide(disk_shape(), Transform2(0.0, Vec2(0.0, 0.5 - sink)), floor_shape(), kFloorPlace,
                   m);
  ASSERT_EQ(m.state(), PairState::kIntersecting);
  const double half_chord = std::sqrt(0.25 - (0.5 - sink) * (0.5 - sink));
  bool left = false, right = false;
  const Vec2 centre(0.0, 0.5 - sink);
  for (const Intersection& x : m.intersections) {
    // Where the circle crosses the face, or (dipped_inside) at a disk segment that dips into
    // the floor by less than the band: inside both bodies, within the band of the face.
    const bool on_face = std::abs(x.point.y()) < 1e-9;
    EXPECT_TRUE(on_face ||
                (x.point.y() < 0.0 && x.point.y() > -0.002 && (x.point - centre).norm() < 0.5))
        << x.point.transpose();
    left |= on_face && std::abs(x.point.x() + half_chord) < 1e-5;
    right |= on_face && std::abs(x.point.x() - half_chord) < 1e-5;
  }
  EXPECT_TRUE(left);
  EXPECT_TRUE(right);
}

TEST(BodyPairCollider, FlatBoxOnFlatFloorGivesSeveralDistinctContacts) {
  const CollisionShape block = make_shape(box_control_points(0.6, 0.2, 32), 0.001 / 0.9);
  BodyPairCollider collider;
  ContactManifold m;
  collider.collide(block, Transform2(0.0, Vec2(0.1, 0.1 + 0.0005)), floor_shape(), kFloorPlace, m);
  ASSERT_EQ(m.state(), PairState::kContact);
  ASSERT_GE(m.contacts.size(), 2u);
  double lo = 1e9, hi = -1e9;
  for (const Contact& c : m.contacts) {
    EXPECT_NEAR(c.distance, 0.0005, 1e-12);
    EXPECT_NEAR(c.normal.y(), 1.0, 1e-12);
    EXPECT_NEAR(c.point.y(), 0.00025, 1e-12);
    lo = std::min(lo, c.point.x());
    hi = std::max(hi, c.point.x());
  }
  // The contacts span the block's bottom face, corners included.
  EXPECT_NEAR(lo, 0.1 - 0.3, 1e-9);
  EXPECT_NEAR(hi, 0.1 + 0.3, 1e-9);
  for (std::size_t i = 0; i < m.contacts.size(); ++i) {
    for (std::size_t j = i + 1; j < m.contacts.size(); ++j) {
      EXPECT_GT((m.contacts[i].point - m.contacts[j].point).norm(), 0.002) << i << " " << j;
    }
  }
}

// All pairs (segment of A, segment of B) that cross, by a dense polyline test.
std::set<std::pair<std::size_t, std::size_t>> brute_force_crossings(const CollisionShape& a,
                                                                    const Transform2& pa,
                                                                    const CollisionShape& b,
                                                                    const Transform2& pb) {
  const int k = 64;
  auto polyline = [&](const CollisionShape& s, const Transform2& p, std::size_t j) {
    std::vector<Vec2> out;
    for (int i = 0; i <= k; ++i)
      out.push_back(p.apply(s.curve().point(j, static_cast<double>(i) / k)));
    return out;
  };
  auto crosses = [](const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
    const double d1 = cross(q - p, r - p), d2 = cross(q - p, s - p);
    const double d3 = cross(s - r, p - r), d4 = cross(s - r, q - r);
    return d1 * d2 < 0 && d3 * d4 < 0;  // proper crossings only: robust verdicts
  };
  std::set<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < a.curve().size(); ++i) {
    const auto la = polyline(a, pa, i);
    for (std::size_t j = 0; j < b.curve().size(); ++j) {
      const auto lb = polyline(b, pb, j);
      for (int u = 0; u < k && !out.count({i, j}); ++u) {
        for (int v = 0; v < k; ++v) {
          if (crosses(la[static_cast<std::size_t>(u)], la[static_cast<std::size_t>(u) + 1],
                      lb[static_cast<std::size_t>(v)], lb[static_cast<std::size_t>(v) + 1])) {
            out.insert({i, j});
            break;
          }
        }
      }
    }
  }
  return out;
}

TEST(BodyPairCollider, EveryCrossingSegmentPairIsReported) {
  Rng rng(61);
  BodyPairCollider collider;
  ContactManifold m;
  std::size_t crossings = 0;
  for (int c = 0; c < 20; ++c) {
    const CollisionShape a = make_shape(
        blob_control_points(1.0, rng.uniform(0.0, 0.7),
                            16 + static_cast<std::size_t>(rng.uniform(0, 24)), rng.next_u64()),
        0.002);
    const CollisionShape b = make_shape(
        blob_control_points(0.7, rng.uniform(0.0, 0.7),
                            12 + static_cast<std::size_t>(rng.uniform(0, 24)), rng.next_u64()),
        0.003);
    const Transform2 pa(rng.uniform(-3, 3), Vec2(0, 0));
    const Transform2 pb(rng.uniform(-3, 3), Vec2(rng.uniform(0.8, 1.4), rng.uniform(-0.5, 0.5)));
    collider.collide(a, pa, b, pb, m);
    std::set<std::pair<std::size_t, std::size_t>> found;
    for (const Intersection& x : m.intersections)
      found.insert({x.segment_a, x.segment_b});
    for (const auto& pair : brute_force_crossings(a, pa, b, pb)) {
      ++crossings;
      EXPECT_TRUE(found.count(pair)) << "case " << c << ": segments " << pair.first << ", "
                                     << pair.second << " cross but were not reported";
    }
  }
  EXPECT_GE(crossings, 40u);  // the layouts do overlap
}

void expect_same_manifold(const ContactManifold& x, const ContactManifold& y, int step) {
  ASSERT_EQ(x.intersections.size(), y.intersections.size()) << "step " << step;
  for (std::size_t i = 0; i < x.intersections.size(); ++i) {
    EXPECT_EQ(x.intersections[i].segment_a, y.intersections[i].segment_a) << "step " << step;
    EXPECT_EQ(x.intersections[i].segment_b, y.intersections[i].segment_b);
    EXPECT_EQ(x.intersections[i].point, y.intersections[i].point);
  }
  ASSERT_EQ(x.contacts.size(), y.contacts.size()) << "step " << step;
  for (std::size_t i = 0; i < x.contacts.size(); ++i) {
    EXPECT_EQ(x.contacts[i].segment_a, y.contacts[i].segment_a) << "step " << step;
    EXPECT_EQ(x.contacts[i].segment_b, y.contacts[i].segment_b);
    EXPECT_EQ(x.contacts[i].t_a, y.contacts[i].t_a);
    EXPECT_EQ(x.contacts[i].t_b, y.contacts[i].t_b);
    EXPECT_EQ(x.contacts[i].point, y.contacts[i].point);
    EXPECT_EQ(x.contacts[i].normal, y.contacts[i].normal);
  }
}

struct CacheRun {
  int touching = 0;  // steps with the pair in contact or crossing
  int queries = 0;   // steps that queried the trees again
};

// Two shapes wandering around each other (small moves, as in a resting pile, and jumps past the
// cache's margin): at every step the cache must give the very manifold of a fresh query.
CacheRun expect_cache_changes_nothing(const CollisionShape& a, const CollisionShape& b,
                                      const NarrowPhaseSettings& settings, std::uint64_t seed) {
  Rng rng(seed);
  BodyPairCollider cached_collider(settings), fresh_collider(settings);
  LeafPairCache cache;
  ContactManifold with_cache, fresh;
  double angle_b = 0.0;
  Vec2 position_b(0.17, 0.02);
  CacheRun run;
  const Transform2 place_a(0.3, Vec2(0.0, 0.0));
  for (int step = 0; step < 3000; ++step) {
    if (rng.uniform() < 0.01) {
      // A jump: somewhere else around A, near or apart.
      angle_b = rng.uniform(0.0, 2.0 * std::numbers::pi);
      const double bearing = rng.uniform(0.0, 2.0 * std::numbers::pi);
      position_b = rng.uniform(0.12, 0.25) * Vec2(std::cos(bearing), std::sin(bearing));
    } else {
      angle_b += rng.uniform(-2e-3, 2e-3);
      position_b += Vec2(rng.uniform(-2e-4, 2e-4), rng.uniform(-2e-4, 2e-4));
    }
    const Transform2 place_b(angle_b, position_b);
    const std::vector<LeafPair> before = cache.candidates;
    const Transform2 cached_at = cache.b_to_a;
    cached_collider.collide(a, place_a, b, place_b, with_cache, &cache);
    fresh_collider.collide(a, place_a, b, place_b, fresh);
    run.queries +=
        cache.candidates != before || cache.b_to_a.translation() != cached_at.translation() ? 1 : 0;
    expect_same_manifold(with_cache, fresh, step);
    EXPECT_EQ(cached_collider.last_leaf_pairs(), fresh_collider.last_leaf_pairs()) << step;
    run.touching += fresh.state() != PairState::kSeparated ? 1 : 0;
  }
  return run;
}

// The leaf-pair cache changes nothing, while the trees are queried only now and then.
TEST(BodyPairCollider, LeafPairCacheGivesTheSameManifoldsAsFreshQueries) {
  const CollisionShape a = make_shape(blob_control_points(0.1, 0.4, 24, 11), 0.003);
  const CollisionShape b = make_shape(blob_control_points(0.1, 0.4, 24, 12), 0.003);
  const CacheRun run = expect_cache_changes_nothing(a, b, {}, 31);
  RecordProperty("queries", std::to_string(run.queries));
  EXPECT_GT(run.touching, 300);
  EXPECT_LT(run.queries, 1500) << "the cache should spare most queries";
}

// Without rugosity and at a coarse accuracy "touching" (crossing_distance) is wider than the
// band: a candidate is proved apart only beyond both.
TEST(BodyPairCollider, LeafPairCacheHoldsWhereTouchingIsWiderThanTheBand) {
  const CollisionShape a = make_shape(blob_control_points(0.1, 0.4, 24, 13), 0.0);
  const CollisionShape b = make_shape(blob_control_points(0.1, 0.4, 24, 14), 0.0);
  NarrowPhaseSettings coarse;
  coarse.relative_accuracy = 1e-4;
  ASSERT_GT(crossing_distance(a.curve().segment(0), b.curve().segment(0), coarse),
            a.segment_band(0) + b.segment_band(0));
  const CacheRun run = expect_cache_changes_nothing(a, b, coarse, 37);
  EXPECT_GT(run.touching, 300);
}

// A cache belongs to the shapes it was made for, not to where they lie in memory: shapes made
// again at the same address (as a scene reloaded into the same storage) query afresh.
TEST(BodyPairCollider, LeafPairCacheIsNotFooledByShapesMadeAtTheSameAddress) {
  std::optional<CollisionShape> a, b;
  a.emplace(make_shape(blob_control_points(0.1, 0.4, 24, 11), 0.003));
  b.emplace(make_shape(blob_control_points(0.1, 0.4, 24, 12), 0.003));
  const Transform2 place_a(0.3, Vec2(0.0, 0.0));
  const Transform2 place_b(0.5, Vec2(0.17, 0.02));
  BodyPairCollider collider;
  LeafPairCache cache;
  ContactManifold with_cache, fresh;
  collider.collide(*a, place_a, *b, place_b, with_cache, &cache);
  // Other outlines in the same storage, placed as before: the first query's leaf pairs mean
  // nothing for them (the old trees had other leaves).
  a.emplace(make_shape(circle_control_points(0.15, 32), 0.003));
  b.emplace(make_shape(circle_control_points(0.03, 16), 0.003));
  collider.collide(*a, place_a, *b, place_b, with_cache, &cache);
  BodyPairCollider fresh_collider;
  fresh_collider.collide(*a, place_a, *b, place_b, fresh);
  ASSERT_NE(fresh.state(), PairState::kSeparated);
  expect_same_manifold(with_cache, fresh, 0);
}

TEST(CollisionPipeline, FindsEveryTouchingPairOnceAndSkipsFixedPairs) {
  // Two fixed floors side by side touching each other, a disk resting across the joint region
  // and a far-away disk.
  std::vector<PlacedShape> bodies = {
      {&floor_shape(), Transform2(0.0, Vec2(-2.0, -0.2)), true, false},
      {&floor_shape(), Transform2(0.0, Vec2(2.0 + 0.0005, -0.2)), true, false},
      {&disk_shape(), Transform2(0.0, Vec2(-1.0, 0.5 + 0.001)), false, false},
      {&disk_shape(), Transform2(0.0, Vec2(1.0, 3.0)), false, false},
  };
  CollisionPipeline pipeline;
  const auto& manifolds = pipeline.detect(bodies);
  ASSERT_EQ(manifolds.size(), 1u);  // floors touch each other but are both fixed
  EXPECT_EQ(manifolds[0].body_a, 0u);
  EXPECT_EQ(manifolds[0].body_b, 2u);
  EXPECT_EQ(manifolds[0].state(), PairState::kContact);
  EXPECT_EQ(pipeline.counts().contacts, 1u);
  EXPECT_GE(pipeline.counts().leaf_pairs, 1u);
}

// A pool of threads changes nothing but the speed: a crowd of rough blobs, moved step after step,
// gives the same manifolds (and counts) with 1, 2, 3 and 8 threads.
TEST(CollisionPipeline, ThreadsGiveTheSameManifolds) {
  std::vector<CollisionShape> shapes;
  for (std::uint64_t i = 0; i < 40; ++i)
    shapes.push_back(make_shape(blob_control_points(0.1, 0.4, 24, 100 + i), 0.003));
  Rng rng(41);
  std::vector<Transform2> places;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    places.emplace_back(rng.uniform(0.0, 6.3),
                        Vec2(0.17 * static_cast<double>(i % 8), 0.17 * static_cast<double>(i / 8)));
  }
  std::vector<CollisionPipeline> pipelines(4);
  std::vector<std::unique_ptr<ThreadPool>> pools;
  for (const int threads : {2, 3, 8})
    pools.push_back(std::make_unique<ThreadPool>(threads));
  int compared = 0;
  for (int step = 0; step < 60; ++step) {
    std::vector<PlacedShape> placed;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      places[i] =
          Transform2(0.0, Vec2(rng.uniform(-2e-3, 2e-3), rng.uniform(-2e-3, 2e-3))) * places[i];
      placed.push_back({&shapes[i], places[i], false, false});
    }
    const std::vector<ContactManifold> reference = pipelines[0].detect(placed);
    for (std::size_t p = 0; p < pools.size(); ++p) {
      const std::vector<ContactManifold>& threaded =
          pipelines[p + 1].detect(placed, pools[p].get());
      ASSERT_EQ(threaded.size(), reference.size()) << "step " << step;
      for (std::size_t m = 0; m < reference.size(); ++m) {
        EXPECT_EQ(threaded[m].body_a, reference[m].body_a);
        EXPECT_EQ(threaded[m].body_b, reference[m].body_b);
        expect_same_manifold(threaded[m], reference[m], step);
      }
      EXPECT_EQ(pipelines[p + 1].counts().leaf_pairs, pipelines[0].counts().leaf_pairs);
      compared += static_cast<int>(reference.size());
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(OutwardNormal, PointsOutOfACircleAndOffASharpCorner) {
  const PeriodicBSpline circle(circle_control_points(1.0, 16));
  for (std::size_t j = 0; j < 16; ++j) {
    const Vec2 n = outward_normal(circle.segment(j), 0.3);
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_GT(n.dot(circle.point(j, 0.3).normalized()), 0.99);
  }
  // A sharp box: the first segment starts at the bottom-left corner with zero tangent and runs
  // along the bottom edge, whose outward normal is −y.
  const PeriodicBSpline box(box_control_points(2.0, 1.0, 16));
  const CubicSegment& s = box.segment(1);  // uses the triple corner point c_0, c_1, c_2
  ASSERT_LE(s.derivative(0.0).norm(), 1e-15);
  const Vec2 n = outward_normal(s, 0.0);
  EXPECT_NEAR(n.x(), 0.0, 1e-12);
  EXPECT_NEAR(n.y(), -1.0, 1e-12);
}

}  // namespace
}  // namespace rugosim

namespace rugosim {
namespace {

TEST(BodyPairCollider, BoxOnFloorKeepsBothCornersWhereverItStands) {
  // Flat on flat: every leaf pair's nearest points sit at segment ends, and equal distances
  // make the order of candidates a matter of rounding. Both corners of the block must survive,
  // wherever it stands.
  const CollisionShape block = make_shape(box_control_points(0.6, 0.2, 32), 0.001 / 0.9);
  BodyPairCollider collider;
  ContactManifold m;
  for (int k = 0; k < 50; ++k) {
    const double x = -1.0 + 0.0371 * k;
    const double tilt = (k % 3 - 1) * 1e-9;
    collider.collide(block, Transform2(tilt, Vec2(x, 0.1 + 0.0005)), floor_shape(), kFloorPlace, m);
    ASSERT_EQ(m.state(), PairState::kContact) << k;
    double lo = 1e9, hi = -1e9;
    for (const Contact& c : m.contacts) {
      lo = std::min(lo, c.point.x());
      hi = std::max(hi, c.point.x());
    }
    EXPECT_NEAR(lo, x - 0.3, 1e-6) << k;
    EXPECT_NEAR(hi, x + 0.3, 1e-6) << k;
    // Every kept contact lies under the block's bottom face, in the band.
    for (const Contact& c : m.contacts) {
      EXPECT_GE(c.point.x(), x - 0.3 - 1e-6);
      EXPECT_LE(c.point.x(), x + 0.3 + 1e-6);
      EXPECT_NEAR(c.distance, 0.0005, 1e-6);
    }
  }
}

TEST(BodyPairCollider, WithoutRugosityTheMinimumBandStillGivesContacts) {
  // σ = 0 on both: a gap of 1e-7 (below the 1e-6-of-size minimum band) is a contact, 1e-5 is
  // apart, and crossing is still crossing.
  const CollisionShape smooth_disk = make_shape(circle_control_points(0.5, 64), 0.0);
  const CollisionShape smooth_floor = make_shape(box_control_points(4.0, 0.4, 48), 0.0);
  BodyPairCollider collider;
  ContactManifold m;
  collider.collide(smooth_disk, Transform2(0.0, Vec2(0.0, 0.5 + 1e-7)), smooth_floor, kFloorPlace,
                   m);
  EXPECT_EQ(m.state(), PairState::kContact);
  collider.collide(smooth_disk, Transform2(0.0, Vec2(0.0, 0.5 + 1e-5)), smooth_floor, kFloorPlace,
                   m);
  EXPECT_EQ(m.state(), PairState::kSeparated);
  collider.collide(smooth_disk, Transform2(0.0, Vec2(0.0, 0.5 - 1e-5)), smooth_floor, kFloorPlace,
                   m);
  EXPECT_EQ(m.state(), PairState::kIntersecting);
}

TEST(MergeDuplicateContacts, MergesOnlyTheSamePlaceOnNeighbouringSegments) {
  auto contact = [](std::size_t sa, std::size_t sb, double x, double distance) {
    Contact c;
    c.segment_a = sa;
    c.segment_b = sb;
    c.lambda_a = c.lambda_b = 0.001;
    c.point_a = Vec2(x, distance);
    c.point_b = Vec2(x, 0.0);
    c.point = Vec2(x, distance / 2);
    c.distance = distance;
    return c;
  };
  std::vector<Contact> contacts = {
      contact(3, 7, 1.0, 0.0010),          // a joint, found by pair (3, 7) ...
      contact(4, 7, 1.0 + 1e-15, 0.0010),  // ... and by its neighbour (4, 7): merged
      contact(4, 8, 1.05, 0.0012),         // adjacent segments but 5 cm away: kept
      contact(9, 7, 1.0005, 0.0011),       // within the band but not a neighbour of 3 or 4: kept
  };
  merge_duplicate_contacts(contacts, 16, 16);
  ASSERT_EQ(contacts.size(), 3u);
  EXPECT_EQ(contacts[0].segment_a, 3u);  // the closest of the merged pair (tie: lower segment)
  EXPECT_EQ(contacts[1].segment_a, 4u);
  EXPECT_EQ(contacts[1].segment_b, 8u);
  EXPECT_EQ(contacts[2].segment_a, 9u);
}

}  // namespace
}  // namespace rugosim
