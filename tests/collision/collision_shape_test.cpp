#include "engine/collision/collision_shape.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/random.h"
#include "engine/geometry/shapes.h"

namespace rugosim {
namespace {

CollisionShape shape_with(const std::vector<double>& lambda) {
  PeriodicBSpline curve(circle_control_points(0.2, lambda.size()));
  return CollisionShape(std::move(curve), ToleranceProfile(lambda));
}

// The least band is a lower bound of λ(t) everywhere on the boundary (checked against a dense
// sampling of the profile, seeded random λ's with zeros among them) and never below min_band.
TEST(CollisionShape, LeastBandBoundsTheBandEverywhereFromBelow) {
  Rng rng(5);
  for (int c = 0; c < 100; ++c) {
    const std::size_t n = 4 + static_cast<std::size_t>(rng.uniform(0.0, 20.0));
    std::vector<double> lambda(n);
    for (double& l : lambda)
      l = rng.uniform() < 0.2 ? 0.0 : rng.uniform(1e-4, 5e-3);
    const CollisionShape shape = shape_with(lambda);
    double sampled = 1.0;
    for (std::size_t j = 0; j < n; ++j) {
      for (int k = 0; k <= 64; ++k)
        sampled = std::min(sampled, shape.tolerances().at(j, k / 64.0));
    }
    EXPECT_LE(shape.least_band(), std::max(sampled, shape.min_band())) << "case " << c;
    EXPECT_GE(shape.least_band(), shape.min_band()) << "case " << c;
  }
}

// Equal λ everywhere: the least band is that λ; a body without rugosity brings min_band only.
TEST(CollisionShape, LeastBandOfAnEvenBandIsItsValue) {
  EXPECT_EQ(shape_with(std::vector<double>(16, 2e-3)).least_band(), 2e-3);
  const CollisionShape smooth = shape_with(std::vector<double>(16, 0.0));
  EXPECT_EQ(smooth.least_band(), smooth.min_band());
}

}  // namespace
}  // namespace rugosim
