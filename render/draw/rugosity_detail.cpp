#include "render/draw/rugosity_detail.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/core/random.h"
#include "engine/geometry/subdivision.h"
#include "engine/geometry/tolerance_profile.h"

namespace rugosim {
namespace {

double mean_spacing(const std::vector<Vec2>& polygon) {
  double length = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    length += (polygon[(i + 1) % polygon.size()] - polygon[i]).norm();
  }
  return length / static_cast<double>(polygon.size());
}

double signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

int detail_level(const std::vector<Vec2>& control, const DetailSettings& s) {
  const double target = s.spacing_px * s.pixel_size;
  int level = 0;
  double spacing = mean_spacing(control);
  std::size_t points = control.size();
  while (level < s.max_level && spacing * 0.5 >= target && points * 2 <= s.max_points) {
    spacing *= 0.5;
    points *= 2;
    ++level;
  }
  return level;
}

}  // namespace

DetailOutline make_detail_outline(const PeriodicBSpline& curve, std::span<const double> sigma,
                                  std::uint64_t seed, const DetailSettings& settings) {
  if (!(settings.pixel_size > 0.0) || !std::isfinite(settings.pixel_size)) {
    throw std::invalid_argument("detail outline: the pixel size must be positive");
  }
  if (sigma.size() != curve.size()) {
    throw std::invalid_argument("detail outline: one σ per segment expected");
  }
  DetailOutline out;
  out.level = detail_level(curve.control_points(), settings);
  std::vector<Vec2> fine = curve.control_points();
  for (int l = 0; l < out.level; ++l)
    fine = subdivide_control_points(fine);
  const std::size_t n = fine.size();
  const double scale = std::ldexp(1.0, -out.level);  // coarse parameter per fine index

  // σ(u) continuous along the boundary: the tolerance profile with q = 1 interpolates σ_j
  // exactly as λ(s) interpolates λ_j.
  const ToleranceProfile profile = ToleranceProfile::from_sigma(sigma, 1.0);
  const bool rough = std::any_of(sigma.begin(), sigma.end(), [](double s) { return s > 0.0; });
  const double outward = signed_area(fine) >= 0.0 ? 1.0 : -1.0;
  if (rough) {
    // One stream per level, so a clip at another resolution draws other detail of the same
    // statistics, and the same resolution always the same detail.
    Rng rng(derive_seed(seed, static_cast<std::uint64_t>(out.level)));
    std::vector<Vec2> displaced(fine);
    for (std::size_t k = 0; k < n; ++k) {
      const double u = static_cast<double>(k) * scale;  // fine control point k sits at u
      const auto j = static_cast<std::size_t>(u);
      const double s = profile.at(j % curve.size(), u - static_cast<double>(j));
      const Vec2 tangent = fine[(k + 1) % n] - fine[(k + n - 1) % n];
      const double length = tangent.norm();
      const double noise =
          std::clamp(rng.normal(), -settings.clamp_sigmas, settings.clamp_sigmas) * s;
      if (length > 0.0) {
        displaced[k] += (outward * noise / length) * Vec2(tangent.y(), -tangent.x());
      }
    }
    fine = std::move(displaced);
  }
  // The B-spline of the displaced points, sampled at its joints: (c[k−1] + 4c[k] + c[k+1]) / 6
  // is the curve at u = k, and the joints are no closer than the detail is fine.
  out.points.reserve(n);
  out.param.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    out.points.push_back((fine[(k + n - 1) % n] + 4.0 * fine[k] + fine[(k + 1) % n]) / 6.0);
    out.param.push_back(static_cast<double>(k) * scale);
  }
  if (outward < 0.0) {
    std::reverse(out.points.begin(), out.points.end());
    std::reverse(out.param.begin(), out.param.end());
  }
  return out;
}

}  // namespace rugosim
