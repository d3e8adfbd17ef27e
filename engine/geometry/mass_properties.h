// Area, centroid and polar second moment of the region a closed periodic cubic B-spline
// encloses, exactly from the curve by Green's theorem over its polynomial segments (DESIGN.md,
// "Mass properties"; the paper's bodies are rigid laminae of uniform density).
#pragma once

#include "engine/core/types.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim {

// A boundary whose |area| is at most this fraction of its hull diagonal squared encloses no
// area worth the name: its centroid is noise. Shared with the boundary validity check.
inline constexpr double kMinRelativeArea = 1e-12;

// Mass properties of a uniform lamina per unit density, in the frame of the control points.
struct MassProperties {
  double area = 0.0;             // m², positive whatever the orientation of the curve
  Vec2 centroid = Vec2::Zero();  // m
  double polar_moment = 0.0;     // m⁴, ∫∫ |x − centroid|² dA (the polar second moment)

  // Areal density in kg/m² (a volume density times the thickness) gives kg.
  double mass(double density) const { return density * area; }
  // kg·m², about the centroid.
  double inertia(double density) const { return density * polar_moment; }
};

// ½ ∮ (x dy − y dx), m²: positive when the curve runs counter-clockwise.
double signed_area(const PeriodicBSpline& curve);

// Exact to rounding for either orientation (every integral flips sign with the orientation,
// so the signed ones are divided by the same signed area). Throws std::invalid_argument when
// the area is not finite or at most kMinRelativeArea times the hull diagonal squared.
MassProperties compute_mass_properties(const PeriodicBSpline& curve);

}  // namespace rugosim
