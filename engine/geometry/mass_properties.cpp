// Mass properties by Green's theorem (DESIGN.md, "Mass properties come exactly from the
// curve"). For a function g homogeneous of degree k, ∂(g x)/∂x + ∂(g y)/∂y = (k + 2) g (Euler),
// so Green's theorem gives
//     ∫∫ g dA = 1/(k + 2) ∮ g (x dy − y dx),
// which with g = 1, x, y, x² + y² yields area, first moments and the polar second moment from
// one rotation-invariant integrand per segment. On a segment x(t), y(t) are cubics in t, so
// w(t) = x y' − y x' is a polynomial (degree 4 after the t⁵ terms cancel) and every integrand
// is a polynomial of degree at most 10: we multiply the power-basis coefficients out and use
// ∫₀¹ tᵏ dt = 1/(k + 1), which is exact up to rounding (no quadrature rule involved).
#include "engine/geometry/mass_properties.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>

namespace rugosim {
namespace {

// Coefficients c[k] of tᵏ.
template <std::size_t N>
using Poly = std::array<double, N>;

template <std::size_t N, std::size_t M>
Poly<N + M - 1> multiply(const Poly<N>& p, const Poly<M>& q) {
  Poly<N + M - 1> r{};
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < M; ++j)
      r[i + j] += p[i] * q[j];
  }
  return r;
}

template <std::size_t N>
Poly<N> subtract(const Poly<N>& p, const Poly<N>& q) {
  Poly<N> r{};
  for (std::size_t i = 0; i < N; ++i)
    r[i] = p[i] - q[i];
  return r;
}

template <std::size_t N>
Poly<N> add(const Poly<N>& p, const Poly<N>& q) {
  Poly<N> r{};
  for (std::size_t i = 0; i < N; ++i)
    r[i] = p[i] + q[i];
  return r;
}

// ∫₀¹ p(t) dt.
template <std::size_t N>
double integrate_unit(const Poly<N>& p) {
  double sum = 0.0;
  for (std::size_t k = N; k-- > 0;)
    sum += p[k] / static_cast<double>(k + 1);
  return sum;
}

// One segment relative to an origin: the coordinates and w = x y' − y x'.
struct SegmentPolys {
  Poly<4> x, y;
  Poly<6> w;
};

SegmentPolys segment_polys(const CubicSegment& s, const Vec2& origin) {
  const auto& a = s.power();
  SegmentPolys p;
  // Subtracting the origin from a0 alone keeps the coordinates small for bodies far from it.
  p.x = {a[0].x() - origin.x(), a[1].x(), a[2].x(), a[3].x()};
  p.y = {a[0].y() - origin.y(), a[1].y(), a[2].y(), a[3].y()};
  const Poly<3> dx{a[1].x(), 2.0 * a[2].x(), 3.0 * a[3].x()};
  const Poly<3> dy{a[1].y(), 2.0 * a[2].y(), 3.0 * a[3].y()};
  p.w = subtract(multiply(p.x, dy), multiply(p.y, dx));
  return p;
}

// Region integrals relative to `origin`, signed by the orientation of the curve.
struct Moments {
  double area = 0.0;          // ∫∫ dA
  Vec2 first = Vec2::Zero();  // ∫∫ (x, y) dA
  double polar = 0.0;         // ∫∫ (x² + y²) dA
};

Moments integrate_moments(const PeriodicBSpline& curve, const Vec2& origin) {
  Moments m;
  for (const CubicSegment& s : curve.segments()) {
    const SegmentPolys p = segment_polys(s, origin);
    m.area += integrate_unit(p.w) / 2.0;
    m.first.x() += integrate_unit(multiply(p.x, p.w)) / 3.0;
    m.first.y() += integrate_unit(multiply(p.y, p.w)) / 3.0;
    const Poly<7> r2 = add(multiply(p.x, p.x), multiply(p.y, p.y));
    m.polar += integrate_unit(multiply(r2, p.w)) / 4.0;
  }
  return m;
}

Vec2 mean_of(const std::vector<Vec2>& points) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& p : points)
    sum += p;
  return sum / static_cast<double>(points.size());
}

}  // namespace

double signed_area(const PeriodicBSpline& curve) {
  const Vec2 origin = mean_of(curve.control_points());
  double area = 0.0;
  for (const CubicSegment& s : curve.segments())
    area += integrate_unit(segment_polys(s, origin).w) / 2.0;
  return area;
}

MassProperties compute_mass_properties(const PeriodicBSpline& curve) {
  // First pass about the mean control point, which is near the body, to find the centroid;
  // second pass about that centroid, so that the polar moment needs no parallel-axis shift
  // of large terms that would cancel.
  const Vec2 mean = mean_of(curve.control_points());
  const Moments rough = integrate_moments(curve, mean);
  const double diagonal = curve.hull_bounds().diagonal();
  if (!std::isfinite(rough.area) ||
      !(std::abs(rough.area) > kMinRelativeArea * diagonal * diagonal)) {
    std::ostringstream message;
    message << "the boundary encloses no area: |A| = " << std::abs(rough.area)
            << " m² with a hull diagonal of " << diagonal << " m";
    throw std::invalid_argument(message.str());
  }
  const Vec2 centre = mean + rough.first / rough.area;
  const Moments m = integrate_moments(curve, centre);
  const double sign = m.area > 0.0 ? 1.0 : -1.0;
  // What is left of the first moment about `centre` is rounding; shift by it exactly.
  const Vec2 residual = m.first / m.area;

  MassProperties props;
  props.area = sign * m.area;
  props.centroid = centre + residual;
  props.polar_moment = sign * m.polar - props.area * residual.squaredNorm();
  return props;
}

}  // namespace rugosim
