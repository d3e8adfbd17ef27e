// Box2D 2.4.1 version of the pile scene, for the wall-time comparison the issue asks for: each
// rugosim body becomes one b2Body made of convex polygon fixtures that approximate the same
// B-spline outline (see box2d_pile.h).
#include "box2d_pile.h"

#include <algorithm>
#include <box2d/box2d.h>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "box2d_units.h"
#include "engine/core/types.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/geometry/periodic_bspline.h"

namespace rugosim::bench {
namespace {

using Polygon = std::vector<Vec2>;  // counter-clockwise vertices in the body frame, Box2D units

constexpr auto kMaxPieceVertices = static_cast<std::size_t>(b2_maxPolygonVertices);
constexpr double kGravity = -9.81;  // m/s², as the rugosim world
// m/s: Box2D's default restitution threshold (impacts slower than this do not bounce), which is
// in Box2D lengths, so it is scaled with them to keep the physics the same at every scale.
constexpr double kRestitutionThreshold = 1.0;

// Box2D lengths: b2PolygonShape::Set welds points closer than half of b2_linearSlop. Keeping
// the vertices of a piece a whole slop apart means it never has to, even after float rounding.
constexpr double kMinVertexSpacing = static_cast<double>(b2_linearSlop);
// Sine of the smallest turn that counts as a corner. A straighter vertex is dropped from the
// outline, and a piece must turn by more at every vertex: Box2D's own hull (computed in float)
// then keeps every vertex we give it, and Validate() holds.
constexpr double kMinTurn = 1e-5;
// Box2D areas: b2PolygonShape's centroid asserts area > b2_epsilon, so pieces not well above it
// are dropped; none are for the pile, and the mass comparison would show it if some were.
constexpr double kMinPieceArea = 16.0 * static_cast<double>(b2_epsilon);

std::size_t next_index(std::size_t i, std::size_t n) {
  return i + 1 == n ? 0 : i + 1;
}
std::size_t previous_index(std::size_t i, std::size_t n) {
  return i == 0 ? n - 1 : i - 1;
}

// a → b → c turns left by more than kMinTurn (as the sine of the turn).
bool turns_left(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 ab = b - a;
  const Vec2 bc = c - b;
  return cross(ab, bc) > kMinTurn * ab.norm() * bc.norm();
}

bool is_convex(const Polygon& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!turns_left(polygon[previous_index(i, n)], polygon[i], polygon[next_index(i, n)]))
      return false;
  }
  return true;
}

double signed_area(const Polygon& polygon) {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    twice_area += cross(polygon[i], polygon[next_index(i, polygon.size())]);
  return 0.5 * twice_area;
}

// Angle (rad, in [0, π]) by which the outline turns at vertex i: 0 where it runs straight on.
double turn_angle(const Polygon& outline, std::size_t i) {
  const std::size_t n = outline.size();
  const Vec2 in = outline[i] - outline[previous_index(i, n)];
  const Vec2 out = outline[next_index(i, n)] - outline[i];
  return std::atan2(std::abs(cross(in, out)), in.dot(out));
}

// The outline at `samples` evenly spaced parameters per segment, scaled to Box2D units and
// counter-clockwise (RigidBody normalises its curve), less the points Box2D could not use: those
// on a straight line (a sharp box's sides, so a rectangle comes out as its four corners) and one
// of each pair closer than kMinVertexSpacing (a sample a hair from a box's corner), the flatter
// one, so that corners survive.
Polygon sample_outline(const PeriodicBSpline& curve, std::size_t samples, double scale) {
  Polygon outline;
  outline.reserve(curve.size() * samples);
  for (std::size_t j = 0; j < curve.size(); ++j) {
    for (std::size_t k = 0; k < samples; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(samples);
      outline.push_back(scale * curve.point(j, t));
    }
  }
  const auto erase = [&outline](std::size_t i) {
    outline.erase(outline.begin() + static_cast<std::ptrdiff_t>(i));
  };
  // Straight points go first, since the corner a close pair straddles may only show once its
  // side is cleared; each removal changes its neighbours' tests, so repeat until nothing moves.
  bool changed = true;
  while (changed && outline.size() >= 3) {
    changed = false;
    for (std::size_t i = 0; i < outline.size() && outline.size() >= 3; ++i) {
      if (turn_angle(outline, i) <= std::asin(kMinTurn)) {
        erase(i);
        changed = true;
      }
    }
    for (std::size_t i = 0; i < outline.size() && outline.size() >= 3 && !changed; ++i) {
      const std::size_t next = next_index(i, outline.size());
      if ((outline[next] - outline[i]).norm() < kMinVertexSpacing) {
        erase(turn_angle(outline, i) < turn_angle(outline, next) ? i : next);
        changed = true;
      }
    }
  }
  if (outline.size() < 3 || signed_area(outline) <= 0.0)
    throw std::runtime_error("box2d_pile: the sampled outline encloses no area");
  return outline;
}

// The pile's blobs are star-shaped around their user origin and, in practice, around their
// centroid too, which is the body-frame origin: then a fan of triangles from the origin covers
// them, and consecutive fan triangles are merged while the piece stays convex and within Box2D's
// vertex limit. Returns nothing when the origin is not strictly inside the outline's kernel (some
// fan triangle is not positive). Greedy merging from a fixed start is optimal along the fan (any
// run inside a convex piece is convex), so only the start is varied, over one piece's worth of
// offsets.
std::optional<std::vector<Polygon>> fan_pieces(const Polygon& outline) {
  const std::size_t n = outline.size();
  const Vec2 origin = Vec2::Zero();
  double turned = 0.0;  // rad, the angle the fan sweeps: 2π once round when star-shaped
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = outline[i];
    const Vec2& b = outline[next_index(i, n)];
    if (!turns_left(origin, a, b) || !turns_left(a, b, origin) || !turns_left(b, origin, a))
      return std::nullopt;
    turned += std::atan2(cross(a, b), a.dot(b));
  }
  // A sampled polygon that wound twice round the origin would pass the triangle test.
  if (std::abs(turned - 2.0 * std::numbers::pi) > 1e-6) return std::nullopt;

  std::vector<Polygon> best;
  for (std::size_t start = 0; start < std::min(n, kMaxPieceVertices); ++start) {
    std::vector<Polygon> pieces;
    Polygon piece{origin, outline[start], outline[next_index(start, n)]};
    for (std::size_t covered = 1; covered < n; ++covered) {
      const Vec2& next = outline[(start + covered + 1) % n];
      Polygon grown = piece;
      grown.push_back(next);
      if (grown.size() <= kMaxPieceVertices && is_convex(grown)) {
        piece = std::move(grown);
      } else {
        const Vec2 last = piece.back();
        pieces.push_back(std::move(piece));
        piece = Polygon{origin, last, next};
      }
    }
    pieces.push_back(std::move(piece));
    if (best.empty() || pieces.size() < best.size()) best = std::move(pieces);
  }
  return best;
}

// Point q in the closed counter-clockwise triangle abc (on an edge counts as in).
bool in_triangle(const Vec2& q, const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross(b - a, q - a) >= 0.0 && cross(c - b, q - c) >= 0.0 && cross(a - c, q - a) >= 0.0;
}

// Ear clipping of a simple counter-clockwise polygon into triangles (as vertex indices): the
// fallback for outlines that are not star-shaped around their centroid.
std::vector<std::vector<std::size_t>> ear_clip(const Polygon& outline) {
  std::vector<std::size_t> left(outline.size());
  std::iota(left.begin(), left.end(), std::size_t{0});
  std::vector<std::vector<std::size_t>> triangles;
  while (left.size() > 3) {
    const std::size_t m = left.size();
    bool clipped = false;
    for (std::size_t i = 0; i < m && !clipped; ++i) {
      const std::size_t ia = left[previous_index(i, m)];
      const std::size_t ib = left[i];
      const std::size_t ic = left[next_index(i, m)];
      const Vec2& a = outline[ia];
      const Vec2& b = outline[ib];
      const Vec2& c = outline[ic];
      if (!turns_left(a, b, c)) continue;
      bool empty = true;
      for (const std::size_t other : left) {
        if (other != ia && other != ib && other != ic && in_triangle(outline[other], a, b, c)) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      triangles.push_back({ia, ib, ic});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    // A simple polygon always has an ear; none means the samples are not a simple polygon.
    if (!clipped) throw std::runtime_error("box2d_pile: the sampled outline has no ear to clip");
  }
  if (turns_left(outline[left[0]], outline[left[1]], outline[left[2]])) triangles.push_back(left);
  return triangles;
}

// Where a → b is an edge of the counter-clockwise index polygon, the position of a; else none.
std::optional<std::size_t> find_edge(const std::vector<std::size_t>& polygon, std::size_t a,
                                     std::size_t b) {
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    if (polygon[i] == a && polygon[next_index(i, polygon.size())] == b) return i;
  }
  return std::nullopt;
}

Polygon points_of(const Polygon& outline, const std::vector<std::size_t>& indices) {
  Polygon points;
  points.reserve(indices.size());
  for (const std::size_t i : indices)
    points.push_back(outline[i]);
  return points;
}

// Greedy merging of triangles across shared edges (Hertel–Mehlhorn style) while the union stays
// convex and within Box2D's vertex limit.
std::vector<Polygon> merge_triangles(const Polygon& outline,
                                     std::vector<std::vector<std::size_t>> pieces) {
  bool merged_any = true;
  while (merged_any) {
    merged_any = false;
    for (std::size_t p = 0; p < pieces.size() && !merged_any; ++p) {
      for (std::size_t q = p + 1; q < pieces.size() && !merged_any; ++q) {
        const std::vector<std::size_t>& first = pieces[p];
        const std::vector<std::size_t>& second = pieces[q];
        if (first.size() + second.size() - 2 > kMaxPieceVertices) continue;
        for (std::size_t i = 0; i < first.size() && !merged_any; ++i) {
          const std::size_t a = first[i];
          const std::size_t b = first[next_index(i, first.size())];
          const std::optional<std::size_t> j = find_edge(second, b, a);
          if (!j) continue;
          // Round the first from b back to a, then the second from after a to before b.
          std::vector<std::size_t> merged;
          for (std::size_t k = 0; k < first.size(); ++k)
            merged.push_back(first[(i + 1 + k) % first.size()]);
          for (std::size_t k = 2; k < second.size(); ++k)
            merged.push_back(second[(*j + k) % second.size()]);
          if (!is_convex(points_of(outline, merged))) continue;
          pieces[p] = std::move(merged);
          pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(q));
          merged_any = true;
        }
      }
    }
  }
  std::vector<Polygon> polygons;
  polygons.reserve(pieces.size());
  for (const std::vector<std::size_t>& piece : pieces)
    polygons.push_back(points_of(outline, piece));
  return polygons;
}

// Convex pieces of at most kMaxPieceVertices vertices that tile the outline: the outline itself
// when it is convex and small enough (the walls), else the fan from the centroid, else ear
// clipping.
std::vector<Polygon> convex_pieces(const Polygon& outline) {
  if (outline.size() <= kMaxPieceVertices && is_convex(outline)) return {outline};
  if (std::optional<std::vector<Polygon>> fan = fan_pieces(outline)) return std::move(*fan);
  return merge_triangles(outline, ear_clip(outline));
}

// The piece in Box2D's floats, or none when Box2D could not take it: b2PolygonShape::Set asserts
// (the Debian library is built with assertions on) on fewer than three points after welding,
// a degenerate hull or an area not above b2_epsilon. The checks are made on the rounded floats,
// since those are what Set sees.
std::optional<std::vector<b2Vec2>> box2d_vertices(const Polygon& piece) {
  if (piece.size() < 3 || piece.size() > kMaxPieceVertices) return std::nullopt;
  std::vector<b2Vec2> vertices;
  Polygon rounded;
  for (const Vec2& p : piece) {
    const b2Vec2 v(static_cast<float>(p.x()), static_cast<float>(p.y()));
    vertices.push_back(v);
    rounded.emplace_back(static_cast<double>(v.x), static_cast<double>(v.y));
  }
  for (std::size_t i = 0; i < rounded.size(); ++i) {
    for (std::size_t k = i + 1; k < rounded.size(); ++k) {
      if ((rounded[i] - rounded[k]).norm() < kMinVertexSpacing) return std::nullopt;
    }
  }
  if (!is_convex(rounded) || signed_area(rounded) <= kMinPieceArea) return std::nullopt;
  return vertices;
}

const Box2dPileOptions& checked(const Box2dPileOptions& options) {
  if (options.samples_per_segment < 1)
    throw std::invalid_argument("box2d_pile: samples_per_segment must be >= 1");
  if (!(std::isfinite(options.length_scale) && options.length_scale > 0.0))
    throw std::invalid_argument("box2d_pile: length_scale must be finite and > 0");
  return options;
}

}  // namespace

Box2dPile::Box2dPile(const std::vector<rugosim::testing::PileBody>& scene,
                     const Box2dPileOptions& options)
    : options_(checked(options)) {
  const double scale = options_.length_scale;
  world_ = std::make_unique<b2World>(to_box2d(Vec2(0.0, kGravity), scale));
  const auto samples = static_cast<std::size_t>(options_.samples_per_segment);
  for (const rugosim::testing::PileBody& entry : scene) {
    // The rugosim body does the normalising and re-centring, so both engines place the same
    // outline about the same centre of mass.
    const RigidBody body(entry.desc);
    const b2BodyDef body_def = box2d_body_def(body, scale);
    b2Body* b2_body = world_->CreateBody(&body_def);

    std::size_t pieces_used = 0;
    for (const Polygon& piece : convex_pieces(sample_outline(body.curve(), samples, scale))) {
      const std::optional<std::vector<b2Vec2>> vertices = box2d_vertices(piece);
      if (!vertices) continue;
      b2PolygonShape shape;
      shape.Set(vertices->data(), static_cast<int32>(vertices->size()));
      if (!shape.Validate())
        throw std::logic_error("box2d_pile: Box2D's hull of a checked piece is not convex");
      b2FixtureDef fixture_def;
      fixture_def.shape = &shape;
      // Areas grow by scale², so the density shrinks by it and the masses stay in kg.
      fixture_def.density = static_cast<float>(body.material().density / (scale * scale));
      fixture_def.friction = static_cast<float>(options_.friction);
      fixture_def.restitution = static_cast<float>(options_.restitution);
      fixture_def.restitutionThreshold = static_cast<float>(kRestitutionThreshold * scale);
      b2_body->CreateFixture(&fixture_def);
      ++pieces_used;
    }
    // Box2D would give a dynamic body without fixtures a mass of 1 kg and carry on silently.
    if (pieces_used == 0)
      throw std::runtime_error("box2d_pile: no convex piece of " + entry.name + " was usable");
    fixture_count_ += pieces_used;
  }
}

Box2dPile::~Box2dPile() = default;
Box2dPile::Box2dPile(Box2dPile&&) noexcept = default;
Box2dPile& Box2dPile::operator=(Box2dPile&&) noexcept = default;

void Box2dPile::step(double dt) {
  world_->Step(static_cast<float>(dt), static_cast<int32>(options_.velocity_iterations),
               static_cast<int32>(options_.position_iterations));
}

std::size_t Box2dPile::body_count() const {
  return static_cast<std::size_t>(world_->GetBodyCount());
}

std::size_t Box2dPile::fixture_count() const {
  return fixture_count_;
}

std::size_t Box2dPile::awake_bodies() const {
  std::size_t awake = 0;
  for (const b2Body* b = world_->GetBodyList(); b != nullptr; b = b->GetNext()) {
    if (b->GetType() == b2_dynamicBody && b->IsAwake()) ++awake;
  }
  return awake;
}

double Box2dPile::kinetic_energy() const {
  double energy = 0.0;
  for (const b2Body* b = world_->GetBodyList(); b != nullptr; b = b->GetNext()) {
    if (b->GetType() != b2_dynamicBody) continue;
    const double mass = static_cast<double>(b->GetMass());
    // GetInertia() is about the body origin; the energy wants it about the centre of mass.
    const b2Vec2& local_centre = b->GetLocalCenter();
    const double inertia = static_cast<double>(b->GetInertia()) -
                           mass * static_cast<double>(local_centre.x * local_centre.x +
                                                      local_centre.y * local_centre.y);
    const b2Vec2& v = b->GetLinearVelocity();  // of the centre of mass
    const double speed_squared = static_cast<double>(v.x) * static_cast<double>(v.x) +
                                 static_cast<double>(v.y) * static_cast<double>(v.y);
    const double omega = static_cast<double>(b->GetAngularVelocity());
    energy += 0.5 * mass * speed_squared + 0.5 * inertia * omega * omega;
  }
  // Masses are in kg whatever the scale, lengths (so velocities and inertias) are scaled.
  const double scale = options_.length_scale;
  return energy / (scale * scale);
}

double Box2dPile::dynamic_mass() const {
  double mass = 0.0;
  for (const b2Body* b = world_->GetBodyList(); b != nullptr; b = b->GetNext()) {
    if (b->GetType() == b2_dynamicBody) mass += static_cast<double>(b->GetMass());
  }
  return mass;
}

double Box2dPile::max_height() const {
  double height = std::numeric_limits<double>::lowest();
  for (const b2Body* b = world_->GetBodyList(); b != nullptr; b = b->GetNext()) {
    if (b->GetType() == b2_dynamicBody)
      height = std::max(height, static_cast<double>(b->GetWorldCenter().y));
  }
  return height / options_.length_scale;
}

}  // namespace rugosim::bench
