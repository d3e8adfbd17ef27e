// Draws docs/images/geometry.svg: a boundary curve, its coarser wavelet levels and its
// rugosity band (the curve offset by ±λ(s) along the normal), straight from the engine.
// Usage: geometry_figure OUT.svg
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <fmt/os.h>

#include "engine/geometry/multiresolution.h"
#include "engine/geometry/periodic_bspline.h"
#include "engine/geometry/rugosity_pattern.h"
#include "engine/geometry/shapes.h"
#include "engine/geometry/tolerance_profile.h"

namespace {

using rugosim::Vec2;

constexpr double kWidth = 1000, kHeight = 580;
constexpr double kScale = 190;                     // pixels per metre
const Vec2 kOrigin(kWidth * 0.3, kHeight * 0.46);  // where the body origin is drawn

Vec2 to_svg(const Vec2& p) {
  return Vec2(kOrigin.x() + kScale * p.x(), kOrigin.y() - kScale * p.y());
}

std::string path_of(const std::vector<Vec2>& points, bool closed) {
  std::string d;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2 q = to_svg(points[i]);
    d += fmt::format("{}{:.2f},{:.2f} ", i == 0 ? "M" : "L", q.x(), q.y());
  }
  if (closed) d += "Z";
  return d;
}

std::vector<Vec2> sample(const rugosim::PeriodicBSpline& curve, int per_segment) {
  std::vector<Vec2> out;
  for (std::size_t j = 0; j < curve.size(); ++j) {
    for (int k = 0; k < per_segment; ++k)
      out.push_back(curve.point(j, static_cast<double>(k) / per_segment));
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: geometry_figure OUT.svg\n");
    return 2;
  }
  const std::size_t n = 64;
  const rugosim::PeriodicBSpline curve(rugosim::blob_control_points(1.0, 0.55, n, 5));
  const rugosim::Multiresolution levels(curve.control_points());
  const auto sigma = rugosim::pattern_sigmas(rugosim::RugosityPattern::kPatches, 0.09, n, 0);
  const auto profile = rugosim::ToleranceProfile::from_sigma(sigma, 0.9);

  // The band: curve ± λ(s) along the unit normal, as one closed outer and inner path.
  std::vector<Vec2> outer, inner;
  const int per_segment = 12;
  for (std::size_t j = 0; j < n; ++j) {
    for (int k = 0; k < per_segment; ++k) {
      const double t = static_cast<double>(k) / per_segment;
      const Vec2 tangent = curve.derivative(j, t);
      const Vec2 normal = Vec2(tangent.y(), -tangent.x()).normalized();  // outward (CCW curve)
      const double lambda = profile.at(j, t);
      outer.push_back(curve.point(j, t) + lambda * normal);
      inner.push_back(curve.point(j, t) - lambda * normal);
    }
  }
  std::vector<Vec2> inner_reversed(inner.rbegin(), inner.rend());

  auto out = fmt::output_file(argv[1]);
  out.print(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" viewBox="0 0 {} {}" font-family="sans-serif">)"
      "\n",
      kWidth, kHeight, kWidth, kHeight);
  out.print(R"(<rect width="100%" height="100%" fill="#f4f1ea"/>)"
            "\n");
  out.print(
      R"(<path d="{} {}" fill="#d9822b" fill-opacity="0.35" fill-rule="evenodd" stroke="none"/>)"
      "\n",
      path_of(outer, true), path_of(inner_reversed, true));

  const char* level_colours[] = {"#1b1b1b", "#1f5fa8", "#3f8fd0", "#6aaee0", "#98c6ea"};
  for (int level = levels.level_count(); level >= 1; --level) {
    const rugosim::PeriodicBSpline coarse(levels.control_points(level));
    out.print(R"(<path d="{}" fill="none" stroke="{}" stroke-width="1.6" stroke-dasharray="6 4"/>)"
              "\n",
              path_of(sample(coarse, 24), true), level_colours[std::min(level, 4)]);
  }
  out.print(R"(<path d="{}" fill="none" stroke="#1b1b1b" stroke-width="2"/>)"
            "\n",
            path_of(sample(curve, 16), true));
  for (const Vec2& c : curve.control_points()) {
    const Vec2 q = to_svg(c);
    out.print(R"(<circle cx="{:.2f}" cy="{:.2f}" r="2.2" fill="#b03030"/>)"
              "\n",
              q.x(), q.y());
  }

  // Legend.
  double y = 60;
  auto legend = [&](const std::string& swatch, const std::string& text) {
    out.print(
        R"svg(<g transform="translate(610,{})">{}<text x="40" y="5" font-size="15" fill="#1b1b1b">{}</text></g>)svg"
        "\n",
        y, swatch, text);
    y += 30;
  };
  legend(R"(<line x1="0" y1="0" x2="30" y2="0" stroke="#1b1b1b" stroke-width="2"/>)",
         fmt::format("C⁰: {} segments", n));
  legend(R"(<circle cx="15" cy="0" r="3" fill="#b03030"/>)", "its control points");
  for (int level = 1; level <= levels.level_count(); ++level) {
    legend(
        fmt::format(
            R"(<line x1="0" y1="0" x2="30" y2="0" stroke="{}" stroke-width="1.6" stroke-dasharray="6 4"/>)",
            level_colours[std::min(level, 4)]),
        fmt::format("C⁻{}: {} segments (wavelet level)", level,
                    levels.control_points(level).size()));
  }
  legend(R"(<rect x="0" y="-8" width="30" height="16" fill="#d9822b" fill-opacity="0.35"/>)",
         "rugosity band ±λ(s), pattern type_4");
  out.print(
      R"(<text x="20" y="{}" font-size="13" fill="#555">λ(s) interpolated between segment midpoints (paper §4.1, erratum fixed); band exaggerated for the picture</text>)"
      "\n",
      kHeight - 14);
  out.print("</svg>\n");
  return 0;
}
