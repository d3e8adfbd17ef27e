#include "engine/scene/model_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/number_text.h"
#include "engine/scene/scene_world.h"

namespace rugosim {
namespace {

std::string number(double x) {
  return number_text(x, 4);
}

}  // namespace

std::vector<SceneError> check_model_limits(const World& world, const Scene& scene,
                                           const std::string& file) {
  std::vector<SceneError> errors;
  auto error = [&](std::size_t i, const std::string& key, const std::string& message) {
    errors.push_back({file, "/bodies/" + std::to_string(i) + "/" + key, message, 0, 0});
  };
  double thinnest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < world.body_count(); ++i)
    thinnest = std::min(thinnest, world.body(i).thickness());
  const double toi = scene_accuracy(scene).toi_tolerance;
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const RigidBody& b = world.body(i);
    const double size = 2.0 * b.bounding_radius();
    if (size < kMinBodySize || size > kMaxBodySize) {
      error(i, "shape",
            "the body is " + number(size) + " m across; expected a body from " +
                number(kMinBodySize) + " to " + number(kMaxBodySize) +
                " m across (rugosim's tolerances are relative to the bodies' sizes, and past "
                "these they meet the limits of double precision)");
      continue;
    }
    const double distance = b.state().position.norm();
    if (distance > kMaxDistanceOverSize * size) {
      error(i, "position",
            "the body is " + number(distance) + " m from the origin and " + number(size) +
                " m across; expected it within " + number(kMaxDistanceOverSize) +
                " times its size from the origin (farther, its coordinates cannot resolve "
                "its smallest contact band)");
    }
    const double lambda = b.shape().tolerances().range().hi;
    if (lambda > 0.5 * b.thickness()) {
      error(i, "rugosity",
            "the largest tolerance λ = q·σ of the body is " + number(lambda) +
                " m, more than half its thickness of " + number(b.thickness()) +
                " m (2 × area / perimeter); expected a smaller σ: a contact inside the band "
                "would reach through the body");
    }
    const double speed =
        b.state().velocity.norm() + std::abs(b.state().angular_velocity) * b.bounding_radius();
    const double fastest = 0.25 * thinnest / toi;
    if (!b.fixed() && speed > fastest) {
      error(i, "velocity",
            "the body moves at up to " + number(speed) + " m/s; expected at most " +
                number(fastest) +
                " m/s (a quarter of the thinnest body's thickness per time-of-impact "
                "tolerance), or a smaller toi_tolerance");
    }
  }
  return errors;
}

}  // namespace rugosim
