// A rugosim scene's bodies as Box2D bodies and fixtures (box2d_scene.h lists the choices).
#include "box2d_scene_world.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <fmt/core.h>

#include "box2d_units.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/geometry/shapes.h"

namespace rugosim::bench {
namespace {

// The 32-gon that stands for a disk when options.circles is false, cut into a fan of pieces of
// kGonEdgesPerPiece rim edges around the centre (Box2D polygons have at most
// b2_maxPolygonVertices = 8 vertices: centre + 5 rim points here).
constexpr int kGonVertices = 32;
constexpr int kGonEdgesPerPiece = 4;
static_assert(kGonVertices % kGonEdgesPerPiece == 0);
static_assert(kGonEdgesPerPiece + 2 <= b2_maxPolygonVertices);

// Relative to the body's size: outline points closer than this are one point.
constexpr double kSameTolerance = 1e-9;

void check(const Box2dSceneOptions& options) {
  if (!(std::isfinite(options.hz) && options.hz > 0.0))
    throw std::invalid_argument(fmt::format("box2d_scene: hz must be > 0, got {}", options.hz));
  if (options.velocity_iterations < 1 || options.position_iterations < 0)
    throw std::invalid_argument(
        "box2d_scene: velocity_iterations must be >= 1 and "
        "position_iterations >= 0");
  if (!(std::isfinite(options.length_scale) && options.length_scale > 0.0))
    throw std::invalid_argument("box2d_scene: length_scale must be finite and > 0");
  if (!(std::isfinite(options.restitution_threshold) && options.restitution_threshold >= 0.0))
    throw std::invalid_argument("box2d_scene: restitution_threshold must be finite and >= 0");
}

std::string unsupported(const BodySpec& spec, const std::string& why) {
  return fmt::format("box2d_scene: body \"{}\": {}", spec.name, why);
}

// What every fixture of a body shares: its material, μ and restitution threshold.
b2FixtureDef fixture_template(const RigidBody& body, double mu, const Box2dSceneOptions& options) {
  const double scale = options.length_scale;
  b2FixtureDef def;
  // Areas grow by scale², so the density shrinks by it and the masses stay in kg.
  def.density = static_cast<float>(body.material().density / (scale * scale));
  def.friction = static_cast<float>(mu);
  def.restitution = static_cast<float>(body.material().restitution);
  def.restitutionThreshold = static_cast<float>(options.restitution_threshold * scale);
  return def;
}

// μ of a body whose σ is the same all round (λ(t) is then that constant); throws otherwise.
double uniform_mu(const RigidBody& body, const BodySpec& spec, double gain) {
  if (!body.shape().tolerances().homogeneous())
    throw std::invalid_argument(unsupported(spec,
                                            "μ varies along its boundary, which the Box2D "
                                            "translation supports only for a fixed box"));
  return body.friction_coefficient(0, 0.5, gain);
}

void add_disk(b2Body* b2_body, const RigidBody& body, const BodySpec& spec, double gain,
              const Box2dSceneOptions& options) {
  const double scale = options.length_scale;
  b2FixtureDef def = fixture_template(body, uniform_mu(body, spec, gain), options);
  // The shape is centred on the user's origin, which is body point −c (rigid_body.h).
  const Vec2 centre = -body.centroid_offset();
  const double radius = spec.shape.radius;
  if (options.circles) {
    b2CircleShape circle;
    circle.m_p = to_box2d(centre, scale);
    circle.m_radius = static_cast<float>(scale * radius);
    def.shape = &circle;
    b2_body->CreateFixture(&def);
    return;
  }
  const auto rim = [&](int i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / kGonVertices;
    return to_box2d(centre + radius * Vec2(std::cos(a), std::sin(a)), scale);
  };
  for (int first = 0; first < kGonVertices; first += kGonEdgesPerPiece) {
    b2Vec2 vertices[kGonEdgesPerPiece + 2];
    vertices[0] = to_box2d(centre, scale);
    for (int k = 0; k <= kGonEdgesPerPiece; ++k)
      vertices[k + 1] = rim(first + k);
    b2PolygonShape piece;
    piece.Set(vertices, kGonEdgesPerPiece + 2);
    def.shape = &piece;
    b2_body->CreateFixture(&def);
  }
}

// A stretch of a box's top face, in x from its centre, with one μ.
struct TopRun {
  double from = 0.0;  // m
  double to = 0.0;    // m
  double mu = 0.0;
};

// The top face (+y in the box's own frame) as runs of equal μ, left to right: each stored
// segment of the sharp-cornered curve that lies on it is a straight stretch with the μ of its
// middle, where λ(t) is the segment's own λ_j. Zero-length segments (a corner's repeated control
// points) carry no μ of their own.
std::vector<TopRun> top_face_runs(const RigidBody& body, const BodySpec& spec, double gain) {
  const PeriodicBSpline& curve = body.curve();
  const Vec2 centre = -body.centroid_offset();
  const double half_height = 0.5 * spec.shape.size.y();
  const double same = kSameTolerance * body.bounding_radius();
  std::vector<TopRun> pieces;
  for (std::size_t k = 0; k < curve.size(); ++k) {
    const Vec2 a = curve.point(k, 0.0) - centre;
    const Vec2 b = curve.point(k, 1.0) - centre;
    const bool on_top = std::abs(a.y() - half_height) <= same &&
                        std::abs(b.y() - half_height) <= same && std::abs(b.x() - a.x()) > same;
    if (on_top)
      pieces.push_back({std::min(a.x(), b.x()), std::max(a.x(), b.x()),
                        body.friction_coefficient(k, 0.5, gain)});
  }
  std::sort(pieces.begin(), pieces.end(),
            [](const TopRun& p, const TopRun& q) { return p.from < q.from; });
  std::vector<TopRun> runs;
  for (const TopRun& piece : pieces) {
    if (!runs.empty() && runs.back().mu == piece.mu &&
        std::abs(runs.back().to - piece.from) <= same)
      runs.back().to = piece.to;
    else
      runs.push_back(piece);
  }
  // The runs must tile the face, corner to corner, or the slabs below would leave gaps.
  const double half_width = 0.5 * spec.shape.size.x();
  bool tiled = !runs.empty() && std::abs(runs.front().from + half_width) <= same &&
               std::abs(runs.back().to - half_width) <= same;
  for (std::size_t r = 1; r < runs.size(); ++r)
    tiled = tiled && std::abs(runs[r].from - runs[r - 1].to) <= same;
  if (!tiled) throw std::logic_error("box2d_scene: the top face's segments do not tile it");
  return runs;
}

// A fixed box whose μ varies along its top face (the rough patch floor): one full-height box
// slab under each run of equal μ, with that μ. Box2D has μ per fixture only, so the continuous
// blend of λ(t) from one segment to the next becomes a step at the segments' joint, and the
// sides and bottom take the μ of the slab they bound. Adjacent slabs share an inner face, whose
// top corner a body sliding across the seam could catch on in Box2D ("ghost collisions", which
// its manual answers with chain shapes); a probe of the rough patch's block crossing such a
// seam at 3 m/s, at 60 and 240 Hz, was not caught.
void add_slabs(b2Body* b2_body, const RigidBody& body, const BodySpec& spec, double gain,
               const Box2dSceneOptions& options) {
  const double scale = options.length_scale;
  const Vec2 centre = -body.centroid_offset();
  const double half_height = 0.5 * spec.shape.size.y();
  for (const TopRun& run : top_face_runs(body, spec, gain)) {
    if (scale * (run.to - run.from) <= static_cast<double>(b2_linearSlop))
      throw std::invalid_argument(unsupported(
          spec, "a run of equal μ is narrower than Box2D's linear slop; raise length_scale"));
    b2FixtureDef def = fixture_template(body, run.mu, options);
    b2PolygonShape slab;
    slab.SetAsBox(static_cast<float>(0.5 * scale * (run.to - run.from)),
                  static_cast<float>(scale * half_height),
                  to_box2d(centre + Vec2(0.5 * (run.from + run.to), 0.0), scale), 0.0f);
    def.shape = &slab;
    b2_body->CreateFixture(&def);
  }
}

void add_box(b2Body* b2_body, const RigidBody& body, const BodySpec& spec, double gain,
             const Box2dSceneOptions& options) {
  if (spec.shape.segments < kSharpBoxMinSegments)
    throw std::invalid_argument(unsupported(
        spec, fmt::format("a box of fewer than {} segments has rounded corners, which the Box2D "
                          "translation does not support",
                          kSharpBoxMinSegments)));
  if (!body.shape().tolerances().homogeneous()) {
    if (!body.fixed())
      throw std::invalid_argument(unsupported(
          spec, "μ varies along the boundary of a movable box, which Box2D cannot express"));
    add_slabs(b2_body, body, spec, gain, options);
    return;
  }
  const double scale = options.length_scale;
  b2FixtureDef def = fixture_template(body, uniform_mu(body, spec, gain), options);
  b2PolygonShape box;
  box.SetAsBox(static_cast<float>(0.5 * scale * spec.shape.size.x()),
               static_cast<float>(0.5 * scale * spec.shape.size.y()),
               to_box2d(-body.centroid_offset(), scale), 0.0f);
  def.shape = &box;
  b2_body->CreateFixture(&def);
}

}  // namespace

void MaxFrictionListener::PreSolve(b2Contact* contact, const b2Manifold* /*old_manifold*/) {
  contact->SetFriction(
      std::max(contact->GetFixtureA()->GetFriction(), contact->GetFixtureB()->GetFriction()));
}

Box2dSceneWorld build_box2d_scene(const Scene& scene, const World& world,
                                  const Box2dSceneOptions& options) {
  check(options);
  if (scene.bodies.size() != world.body_count())
    throw std::logic_error("box2d_scene: the World does not hold the scene's bodies");
  const double scale = options.length_scale;
  const double gain = world.settings().friction_gain;
  Box2dSceneWorld out;
  out.scale = scale;
  out.listener = std::make_unique<MaxFrictionListener>();
  out.world = std::make_unique<b2World>(to_box2d(world.settings().gravity, scale));
  out.world->SetContactListener(out.listener.get());
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const RigidBody& body = world.body(i);
    const BodySpec& spec = scene.bodies[i];
    const b2BodyDef def = box2d_body_def(body, scale);
    b2Body* b2_body = out.world->CreateBody(&def);
    switch (spec.shape.kind) {
      case ShapeKind::kCircle:
        add_disk(b2_body, body, spec, gain, options);
        break;
      case ShapeKind::kBox:
        add_box(b2_body, body, spec, gain, options);
        break;
      default:
        throw std::invalid_argument(
            unsupported(spec, "only circles and boxes have a Box2D translation"));
    }
    out.bodies.push_back(b2_body);
  }
  return out;
}

}  // namespace rugosim::bench
