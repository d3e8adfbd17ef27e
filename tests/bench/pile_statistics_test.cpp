// The piles' statistics (bench/pile_statistics.h): the hull area against exact areas, the
// estimates and the t-test against worked values, the perturbation's size and determinism, and
// the measures of a real pile run against what must hold of any pile.
#include "pile_statistics.h"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"

namespace rugosim::study {
namespace {

TEST(ConvexHullArea, OfASquareWithPointsInsideAndOnItsEdges) {
  std::vector<Vec2> points = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 0}, {0.5, 1.5}, {2, 1}};
  EXPECT_DOUBLE_EQ(convex_hull_area(points), 4.0);
  points.push_back({0, 0});  // a duplicate changes nothing
  EXPECT_DOUBLE_EQ(convex_hull_area(points), 4.0);
}

TEST(ConvexHullArea, OfSeededPointsOnARegularPolygonAndInside) {
  Rng rng(17);
  for (const int n : {3, 5, 12, 100}) {
    const double r = rng.uniform(0.1, 10.0);
    std::vector<Vec2> points;
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * std::numbers::pi * k / n;
      points.emplace_back(r * std::cos(a) + 3.0, r * std::sin(a) - 1.0);
    }
    for (int k = 0; k < 50; ++k) {  // inside the inscribed circle
      const double a = rng.uniform(0.0, 2.0 * std::numbers::pi);
      const double s = rng.uniform(0.0, r * std::cos(std::numbers::pi / n));
      points.emplace_back(s * std::cos(a) + 3.0, s * std::sin(a) - 1.0);
    }
    const double exact = 0.5 * n * r * r * std::sin(2.0 * std::numbers::pi / n);
    EXPECT_NEAR(convex_hull_area(points), exact, 1e-12 * exact) << n;
  }
}

TEST(ConvexHullArea, OfTooFewOrCollinearPointsIsZero) {
  EXPECT_EQ(convex_hull_area({}), 0.0);
  EXPECT_EQ(convex_hull_area({{0, 0}, {1, 1}}), 0.0);
  EXPECT_EQ(convex_hull_area({{0, 0}, {1, 1}, {2, 2}, {3, 3}}), 0.0);
}

TEST(Estimate, MeanSpreadAndConfidenceIntervalOfAWorkedSample) {
  const Estimate e = estimate({1.0, 2.0, 3.0, 4.0});
  EXPECT_EQ(e.n, 4u);
  EXPECT_DOUBLE_EQ(e.mean, 2.5);
  EXPECT_NEAR(e.sd, std::sqrt(5.0 / 3.0), 1e-15);
  EXPECT_NEAR(e.half_width, 3.182 * std::sqrt(5.0 / 3.0) / 2.0, 1e-12);  // t(0.975, 3)
  EXPECT_EQ(estimate({7.0}).half_width, 0.0);
}

TEST(StudentT, TableValuesAndTheNormalBeyond) {
  EXPECT_DOUBLE_EQ(t975(1), 12.706);
  EXPECT_DOUBLE_EQ(t975(15), 2.131);
  EXPECT_DOUBLE_EQ(t975(15.7), 2.131);  // fractional dof: the wider bound of the lower row
  EXPECT_DOUBLE_EQ(t975(1000), 1.96);
  for (int dof = 2; dof <= 30; ++dof)
    EXPECT_LT(t975(dof), t975(dof - 1));
  EXPECT_THROW(t975(0.5), std::invalid_argument);
}

TEST(Welch, TellsSeparatedMeansFromOverlappingOnes) {
  const Estimate a = estimate({1.0, 1.1, 0.9, 1.05, 0.95});
  const Estimate b = estimate({2.0, 2.1, 1.9, 2.05, 1.95});
  const Estimate c = estimate({1.02, 1.12, 0.88, 1.0, 0.97});
  EXPECT_TRUE(means_differ(a, b));
  EXPECT_FALSE(means_differ(a, c));
  EXPECT_FALSE(means_differ(a, a));
  // Without spread, only equal means are the same.
  EXPECT_FALSE(means_differ(estimate({3.0, 3.0}), estimate({3.0, 3.0, 3.0})));
  EXPECT_TRUE(means_differ(estimate({3.0, 3.0}), estimate({3.5, 3.5})));
  EXPECT_THROW(means_differ(estimate({1.0}), b), std::invalid_argument);
}

std::string scene_path(const std::string& name) {
  const char* root = std::getenv("RUGOSIM_SOURCE_DIR");
  return std::string(root != nullptr ? root : RUGOSIM_TEST_SOURCE_DIR) + "/scenes/" + name +
         ".json";
}

TEST(PerturbedScene, MovesEachMovableBodyByTheShareOfItsRadiusAndNothingElse) {
  const std::string path = scene_path("figure12a");
  const SceneLoad load = load_scene_file(path);
  ASSERT_TRUE(load.ok()) << path;
  const SceneWorld built = build_world(load.scene, path);
  ASSERT_TRUE(built.world);
  const double share = 1e-6;  // well above the rounding of positions of order 1 m
  const Scene same = perturbed_scene(load.scene, path, 0, share);
  const Scene one = perturbed_scene(load.scene, path, 3, share);
  const Scene again = perturbed_scene(load.scene, path, 3, share);
  const Scene other = perturbed_scene(load.scene, path, 4, share);
  for (std::size_t i = 0; i < load.scene.bodies.size(); ++i) {
    const Vec2 p = load.scene.bodies[i].position;
    EXPECT_EQ(same.bodies[i].position, p);
    EXPECT_EQ(one.bodies[i].position, again.bodies[i].position);
    EXPECT_EQ(one.bodies[i].angle, load.scene.bodies[i].angle);
    EXPECT_EQ(one.bodies[i].velocity, load.scene.bodies[i].velocity);
    if (load.scene.bodies[i].fixed) {
      EXPECT_EQ(one.bodies[i].position, p);
      continue;
    }
    const double r = built.world->body(i).bounding_radius();
    EXPECT_NEAR((one.bodies[i].position - p).norm(), share * r, 1e-9 * share * r);
    EXPECT_NE(one.bodies[i].position, other.bodies[i].position);
  }
}

// A short pile run measured: what holds of any pile, whatever the settings.
TEST(MeasurePile, AFigure12aRunEndsResting) {
  const std::string path = scene_path("figure12a");
  SceneLoad load = load_scene_file(path);
  ASSERT_TRUE(load.ok()) << path;
  load.scene.duration = 2.5;
  const study::Run run = run_scene(load.scene, path, *accuracy_preset("draft"), 1);
  const PileMeasures m = measure_pile(run);
  EXPECT_GT(m.settle_time, 0.1);  // the rocks start in the air
  EXPECT_LE(m.settle_time, load.scene.duration);
  EXPECT_GT(m.packing_fraction, 0.2);
  EXPECT_LT(m.packing_fraction, 1.0);
  ASSERT_EQ(m.contacts.size(), run.movers.size());
  // Every rock at rest touches something (the floor, a wall or a rock), within its bands.
  for (const int c : m.contacts)
    EXPECT_GE(c, 1);
  // Its centre of mass ends below where it started, above the floor (top face y = 0).
  double start = 0.0, mass = 0.0;
  for (std::size_t k = 0; k < run.movers.size(); ++k) {
    const double mk = run.world->body(run.movers[k]).mass();
    start += mk * run.frames.front()[k].position.y();
    mass += mk;
  }
  EXPECT_LT(m.com_height, start / mass);
  EXPECT_GT(m.com_height, 0.0);
}

}  // namespace
}  // namespace rugosim::study
