// Shape generators of the scene format (INTERFACE.md, "Shapes"): control polygons, in the body
// frame and counter-clockwise, for the closed periodic cubic B-spline of a body. Each throws
// std::invalid_argument with the reason when a parameter is out of range.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/types.h"

namespace rugosim {

// Radius of the control polygon whose B-spline passes through radius r at every knot: a
// uniform cubic B-spline pulls a regular polygon in by (4 + 2 cos(2π/n)) / 6 at the knots.
double circle_control_radius(double radius, std::size_t n);

// A circle of radius r (m) centred at the origin; knot points lie exactly on it, and between
// knots the curve dips inside it by about 0.0026·(2π/n)⁴·r (the area falls short of πr² by
// about 4.3/n⁴ of it).
std::vector<Vec2> circle_control_points(double radius, std::size_t n);

// An ellipse with semi-axes a (along x) and b (along y), the affine image of the circle.
std::vector<Vec2> ellipse_control_points(double a, double b, std::size_t n);

// A w x h rectangle centred at the origin. With n >= 12 each corner is a triple control point,
// every segment is straight and the curve is exactly the rectangle (the tangent vanishes at
// the four corners). With 4 <= n < 12 the points are spread evenly along the perimeter and
// the corners are rounded, inside the rectangle.
std::vector<Vec2> box_control_points(double width, double height, std::size_t n);
inline constexpr std::size_t kSharpBoxMinSegments = 12;

// A polygon of k >= 3 corners (in order, either orientation; it must not cross itself), as n >=
// 3k control points. A corner without rounding is a triple point, so the curve passes through
// it sharp and every segment between corners is straight; a corner with rounding r (m, at
// most half its shorter edge) is the corner and a point r along each edge, so the curve turns
// smoothly within about r of it. The n − 3k points left over are spread along the edges by
// length. `rounding` is empty (all sharp) or one length per corner. Throws
// std::invalid_argument for fewer than 3 corners or 3k segments, coinciding neighbours, or a
// rounding out of range.
std::vector<Vec2> polygon_control_points(std::span<const Vec2> corners,
                                         std::span<const double> rounding, std::size_t n);

// A random irregular outline: radius r·(1 + a·g(θ)) with g a seeded sum of low harmonics
// (orders 2..6) scaled so |g| <= 1; a in [0, 0.9]. Concave for large a; always star-shaped
// around the origin, and the same seed gives the same outline.
std::vector<Vec2> blob_control_points(double radius, double irregularity, std::size_t n,
                                      std::uint64_t seed);
inline constexpr double kMaxBlobIrregularity = 0.9;

}  // namespace rugosim
