// Overlap of two oriented boxes by the separating-axis test (paper §3.2): two convex sets are
// disjoint exactly when their projections onto some line are disjoint, and for two rectangles
// it suffices to try the four lines parallel to their sides. Inline: the AOBB tree calls it
// for every pair of boxes it visits.
#pragma once

#include <cmath>

#include "engine/geometry/obb.h"

namespace rugosim {

// True when the boxes share at least one point; touching boxes overlap. Both boxes must be in
// the same frame. With a slack (m, >= 0) every axis allows that much more: true whenever the
// boxes come within `slack` of each other (and a little beyond, at corners), so boxes that
// overlap after either moved by at most `slack` were found before it moved.
inline bool obb_overlap(const Obb& a, const Obb& b, double slack = 0.0) {
  const double dx = b.center.x() - a.center.x();
  const double dy = b.center.y() - a.center.y();
  // |cos| of the angles between the axes of a (rows) and of b (columns).
  const double xx = std::abs(a.axis_x.x() * b.axis_x.x() + a.axis_x.y() * b.axis_x.y());
  const double xy = std::abs(a.axis_x.x() * b.axis_y.x() + a.axis_x.y() * b.axis_y.y());
  const double yx = std::abs(a.axis_y.x() * b.axis_x.x() + a.axis_y.y() * b.axis_x.y());
  const double yy = std::abs(a.axis_y.x() * b.axis_y.x() + a.axis_y.y() * b.axis_y.y());
  const double ahx = a.half_extents.x() + slack, ahy = a.half_extents.y() + slack;
  const double bhx = b.half_extents.x(), bhy = b.half_extents.y();
  // On each axis the boxes are apart when the centres' distance exceeds the sum of the
  // projected half widths; equality is contact, which counts as overlap.
  if (std::abs(dx * a.axis_x.x() + dy * a.axis_x.y()) > ahx + bhx * xx + bhy * xy) return false;
  if (std::abs(dx * a.axis_y.x() + dy * a.axis_y.y()) > ahy + bhx * yx + bhy * yy) return false;
  if (std::abs(dx * b.axis_x.x() + dy * b.axis_x.y()) > bhx + ahx * xx + ahy * yx) return false;
  if (std::abs(dx * b.axis_y.x() + dy * b.axis_y.y()) > bhy + ahx * xy + ahy * yy) return false;
  return true;
}

}  // namespace rugosim
