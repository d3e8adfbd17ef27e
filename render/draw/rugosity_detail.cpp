#include "render/draw/rugosity_detail.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "engine/geometry/curve_length.h"
#include "engine/geometry/tolerance_profile.h"
#include "render/draw/boundary_noise.h"

namespace rugosim {
namespace {

// Arc length at parameter u = j + k/kSteps, k = 0…kSteps, for every segment j: the samples'
// parameters are found by linear interpolation inside these short steps, where the speed
// |c'(u)| barely changes. The table depends on the curve alone, so every pixel size puts a
// given s at the same place.
constexpr int kSteps = 16;

class ArcLengthTable {
 public:
  explicit ArcLengthTable(const PeriodicBSpline& curve) : s_(curve.size() * kSteps + 1, 0.0) {
    for (std::size_t j = 0; j < curve.size(); ++j) {
      for (int k = 0; k < kSteps; ++k) {
        const std::size_t i = j * kSteps + static_cast<std::size_t>(k);
        s_[i + 1] = s_[i] + segment_arc_length(curve.segment(j), k / double{kSteps},
                                               (k + 1) / double{kSteps});
      }
    }
  }
  double length() const { return s_.back(); }
  // The parameter u in [0, n) at arc length s in [0, length).
  double param(double s) const {
    const auto it = std::upper_bound(s_.begin(), s_.end(), s);
    const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - s_.begin() - 1, 0));
    const std::size_t last = s_.size() - 2;
    const std::size_t step = std::min(i, last);
    const double span = s_[step + 1] - s_[step];
    const double f = span > 0.0 ? std::clamp((s - s_[step]) / span, 0.0, 1.0) : 0.0;
    return (static_cast<double>(step) + f) / kSteps;
  }

 private:
  std::vector<double> s_;
};

double signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
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
  if (!(settings.roughness_scale >= 0.0) || !std::isfinite(settings.roughness_scale) ||
      !(settings.correlation_length >= 0.0) || !std::isfinite(settings.correlation_length)) {
    throw std::invalid_argument("detail outline: the roughness scale and ℓ must be ≥ 0");
  }
  const ArcLengthTable table(curve);
  DetailOutline out;
  out.length = table.length();
  // At least four samples a segment, so that a smooth outline stays smooth when zoomed out,
  // and at most max_points (then the octaves too fine for that many are left out).
  const double floor_points = 4.0 * static_cast<double>(curve.size());
  const double most_points = std::max(floor_points, static_cast<double>(settings.max_points));
  const double shortest_step = out.length / most_points;

  const double largest = sigma.empty() ? 0.0 : *std::max_element(sigma.begin(), sigma.end());
  const double amplitude = settings.roughness_scale;
  std::optional<BoundaryNoise> noise;
  if (largest > 0.0 && amplitude > 0.0) {
    out.correlation_length = settings.correlation_length > 0.0 ? settings.correlation_length
                                                               : kCorrelationPerSigma * largest;
    noise.emplace(BoundaryNoiseSpec{.period = out.length,
                                    .correlation_length = out.correlation_length,
                                    .octaves = settings.octaves,
                                    .hurst = settings.hurst,
                                    .clamp_sigmas = settings.clamp_sigmas},
                  seed,
                  std::max(settings.min_cell_px * settings.pixel_size,
                           settings.samples_per_cell * shortest_step));
    out.octaves = noise->octaves_drawn();
  }
  double longest_step = settings.spacing_px * settings.pixel_size;
  if (out.octaves > 0) {
    longest_step = std::min(longest_step, noise->finest_spacing() / settings.samples_per_cell);
  }
  const double wanted = std::ceil(out.length / longest_step);
  const auto n = static_cast<std::size_t>(
      std::clamp(std::isfinite(wanted) ? wanted : 0.0, floor_points, most_points));
  const double step = out.length / static_cast<double>(n);
  // σ(u) continuous along the boundary: the tolerance profile with q = 1 interpolates σ_j
  // exactly as λ(s) interpolates λ_j.
  const ToleranceProfile profile = ToleranceProfile::from_sigma(sigma, 1.0);
  std::vector<Vec2> smooth(n);
  out.param.resize(n);
  out.arc_length.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.arc_length[i] = static_cast<double>(i) * step;
    out.param[i] = table.param(out.arc_length[i]);
    smooth[i] = curve.point_at(out.param[i]);
  }
  const double outward = signed_area(smooth) >= 0.0 ? 1.0 : -1.0;
  out.points = smooth;
  out.displacement.assign(n, 0.0);
  if (noise && out.octaves > 0) {
    for (std::size_t i = 0; i < n; ++i) {
      const double u = out.param[i];
      const auto j = std::min(static_cast<std::size_t>(u), curve.size() - 1);
      const double d =
          amplitude * profile.at(j, u - static_cast<double>(j)) * (*noise)(out.arc_length[i]);
      // The normal of the chord between the neighbours: defined at a sharp corner too (where
      // c'(u) vanishes), and there it bisects the corner.
      const Vec2 tangent = smooth[(i + 1) % n] - smooth[(i + n - 1) % n];
      const double norm = tangent.norm();
      if (norm > 0.0) {
        out.points[i] += (outward * d / norm) * Vec2(tangent.y(), -tangent.x());
        out.displacement[i] = d;
      }
    }
  }
  if (outward < 0.0) {
    std::reverse(out.points.begin(), out.points.end());
    std::reverse(out.param.begin(), out.param.end());
    std::reverse(out.arc_length.begin(), out.arc_length.end());
    std::reverse(out.displacement.begin(), out.displacement.end());
  }
  return out;
}

}  // namespace rugosim
