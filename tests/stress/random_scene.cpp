#include "random_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "engine/core/random.h"

namespace rugosim::testing {
namespace {

using nlohmann::json;

constexpr double kPi = std::numbers::pi;

// Log-uniform in [lo, hi].
double log_uniform(Rng& rng, double lo, double hi) {
  return std::exp(rng.uniform(std::log(lo), std::log(hi)));
}

// prefix followed by k (appended: GCC 12's -Wrestrict misfires on string + to_string at -O3).
std::string numbered(const char* prefix, int k) {
  std::string name(prefix);
  name.append(std::to_string(k));
  return name;
}

int integer(Rng& rng, int lo, int hi) {  // in [lo, hi]
  return lo + static_cast<int>(rng.uniform() * (hi - lo + 1));
}

template <typename T, std::size_t N>
const T& pick(Rng& rng, const std::array<T, N>& options) {
  return options[static_cast<std::size_t>(rng.uniform() * N)];
}

// 4-256 segments, mostly few (the cost of a scene grows with them).
int segment_count(Rng& rng, int at_least) {
  const int n = static_cast<int>(log_uniform(rng, 4.0, 257.0));
  return std::clamp(n, at_least, 256);
}

json material(Rng& rng, double density) {
  const double restitution = rng.uniform();
  return {{"density", density},
          {"restitution", restitution},
          {"restitution_max", rng.uniform(restitution, 1.0)},
          {"lambda_min", rng.uniform() < 0.5 ? 0.0 : rng.uniform(0.0, 0.002)}};
}

json any_density_material(Rng& rng) {
  return material(rng, log_uniform(rng, 1.0, 20000.0));
}

// No rugosity, one σ, one σ per segment, or a pattern; σ up to 4% of the body's size.
std::optional<json> rugosity(Rng& rng, double size, int segments) {
  const double sigma = size * log_uniform(rng, 1e-4, 0.04);
  switch (integer(rng, 0, 3)) {
    case 0:
      return std::nullopt;
    case 1:
      return json{{"sigma", sigma}};
    case 2: {
      json each = json::array();
      for (int j = 0; j < segments; ++j)
        each.push_back(rng.uniform() < 0.3 ? 0.0 : sigma * rng.uniform());
      return json{{"sigma", each}};
    }
    default: {
      static const std::array<std::string, 4> patterns = {"type_1", "type_2", "type_3", "type_4"};
      return json{{"pattern", pick(rng, patterns)}, {"sigma", sigma}};
    }
  }
}

// A shape whose every point lies within `radius` of the body's origin... and within the
// hull a little wider for blobs, which reach out by their irregularity (kept inside radius by
// shrinking their nominal radius).
json shape(Rng& rng, double radius, int* segments) {
  switch (integer(rng, 0, 4)) {
    case 0:
      *segments = segment_count(rng, 4);
      return {{"circle", {{"radius", radius}, {"segments", *segments}}}};
    case 1:
      *segments = segment_count(rng, 4);
      return {{"ellipse",
               {{"radii", {radius, radius * rng.uniform(0.25, 1.0)}}, {"segments", *segments}}}};
    case 2: {
      *segments = segment_count(rng, 12);
      const double h = rng.uniform(0.2, 1.0);
      // Half-diagonal = radius.
      const double w = 2.0 * radius / std::sqrt(1.0 + h * h);
      return {{"box", {{"size", {w, w * h}}, {"segments", *segments}}}};
    }
    case 3: {
      *segments = segment_count(rng, 6);
      const double irregularity = rng.uniform(0.0, 0.6);
      return {{"blob",
               {{"radius", radius / (1.0 + irregularity)},
                {"irregularity", irregularity},
                {"segments", *segments},
                {"seed", rng.next_u64() >> 12}}}};
    }
    default: {
      // A star-shaped polygon of control points: always a simple curve.
      *segments = integer(rng, 4, 24);
      json points = json::array();
      std::vector<double> angles;
      for (int k = 0; k < *segments; ++k)
        angles.push_back((k + rng.uniform(0.1, 0.9)) * 2.0 * kPi / *segments);
      for (const double a : angles) {
        const double r = radius * rng.uniform(0.5, 1.0);
        points.push_back({r * std::cos(a), r * std::sin(a)});
      }
      return {{"control_points", points}};
    }
  }
}

json random_body(Rng& rng, const std::string& name, double radius, double x, double y, double speed,
                 double spin) {
  int segments = 0;
  json body = {{"name", name}, {"shape", shape(rng, radius, &segments)}};
  body["position"] = {x, y};
  body["angle"] = rng.uniform(0.0, 2.0 * kPi);
  const double direction = rng.uniform(0.0, 2.0 * kPi);
  const double v = speed * rng.uniform();
  body["velocity"] = {v * std::cos(direction), v * std::sin(direction)};
  body["angular_velocity"] = spin * rng.uniform(-1.0, 1.0);
  body["material"] = any_density_material(rng);
  if (auto r = rugosity(rng, radius, segments)) body["rugosity"] = *r;
  return body;
}

json fixed_box(const std::string& name, double w, double h, double x, double y) {
  return {{"name", name},
          {"fixed", true},
          {"shape", {{"box", {{"size", {w, h}}, {"segments", 16}}}}},
          {"position", {x, y}}};
}

// Walls of a closed box whose inside is [−w/2, w/2] × [0, h], `t` thick.
void closed_box(json& bodies, double w, double h, double t) {
  bodies.push_back(fixed_box("floor", w + 2.0 * t, t, 0.0, -0.5 * t));
  bodies.push_back(fixed_box("ceiling", w + 2.0 * t, t, 0.0, h + 0.5 * t));
  bodies.push_back(fixed_box("left_wall", t, h, -0.5 * (w + t), 0.5 * h));
  bodies.push_back(fixed_box("right_wall", t, h, 0.5 * (w + t), 0.5 * h));
}

// Bodies of radius at most `radius` on a grid of `columns`, filling upwards from `y0`, each in a
// cell 2.2 radii wide so that none touches another at t = 0.
void grid_of_bodies(Rng& rng, json& bodies, int count, int columns, double radius, double y0,
                    double speed, double spin) {
  const double cell = 2.2 * radius;
  for (int k = 0; k < count; ++k) {
    const double x = (k % columns - 0.5 * (columns - 1)) * cell;
    const double y = y0 + (k / columns + 0.5) * cell;
    const double r = radius * rng.uniform(0.4, 1.0);
    bodies.push_back(random_body(rng, numbered("b", k), r, x, y, speed, spin));
  }
}

// Loose bodies dropped on a floor, or shaken in a closed box.
void loose(Rng& rng, StressScene& s, json& bodies) {
  const int count = integer(rng, 1, 60);
  const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(count))));
  const double r = s.scale;
  const double speed = std::sqrt(9.81 * r) * rng.uniform(0.0, 3.0);
  const double w = columns * 2.2 * r;
  const double h = ((count + columns - 1) / columns + 1) * 2.2 * r;
  if (rng.uniform() < 0.5) {
    closed_box(bodies, w, h, r);
  } else {
    bodies.push_back(fixed_box("floor", 4.0 * w, r, 0.0, -0.5 * r));
  }
  grid_of_bodies(rng, bodies, count, columns, r, 0.0, speed, speed / r);
}

// Boxes stacked on a floor, each placed where the one below ends, summed in floating point:
// faces at distance 0 or a rounding across (touching at t = 0).
void stack(Rng& rng, StressScene& s, json& bodies) {
  const double r = s.scale;
  bodies.push_back(fixed_box("floor", 20.0 * r, r, 0.0, -0.5 * r));
  const int count = integer(rng, 1, 12);
  double y = rng.uniform() < 0.5 ? 0.0 : r * 1e-10 * rng.uniform();
  for (int k = 0; k < count; ++k) {
    const double w = r * rng.uniform(0.5, 2.0);
    const double h = r * rng.uniform(0.2, 1.0);
    json body = {{"name", numbered("crate", k)},
                 {"shape", {{"box", {{"size", {w, h}}, {"segments", integer(rng, 12, 40)}}}}},
                 {"position", {r * rng.uniform(-0.2, 0.2), y + 0.5 * h}},
                 {"material", any_density_material(rng)}};
    bodies.push_back(body);
    y = y + h;
  }
}

// Fast bodies in a closed box, with or without gravity.
void swarm(Rng& rng, StressScene& s, json& bodies, json& world) {
  const double r = s.scale;
  const int count = integer(rng, 8, 60);
  const int columns = std::max(2, static_cast<int>(std::ceil(std::sqrt(count))));
  const double w = columns * 2.2 * r;
  const double h = ((count + columns - 1) / columns) * 2.2 * r;
  closed_box(bodies, w, h, r);
  if (rng.uniform() < 0.5) world["gravity"] = {0.0, 0.0};
  const double speed = r * rng.uniform(5.0, 40.0);  // body sizes per second
  grid_of_bodies(rng, bodies, count, columns, r, 0.0, speed, speed / r * rng.uniform(0.0, 4.0));
}

// A light body between two heavy ones, the upper one coming down fast.
void squeeze(Rng& rng, StressScene& s, json& bodies, json& world) {
  const double r = s.scale;
  const double g = 9.81 * rng.uniform(1.0, 50.0);
  world["gravity"] = {0.0, -g};
  bodies.push_back(fixed_box("ground", 40.0 * r, r, 0.0, -0.5 * r));
  const double heavy = log_uniform(rng, 1000.0, 20000.0);
  const double slab_w = r * rng.uniform(4.0, 20.0);
  bodies.push_back({{"name", "slab"},
                    {"shape", {{"box", {{"size", {slab_w, r}}, {"segments", 32}}}}},
                    {"position", {0.0, 0.5 * r + r * 1e-3}},
                    {"material", material(rng, heavy)}});
  const double light_r = 0.5 * r * rng.uniform(0.3, 1.0);
  json light = random_body(rng, "light", light_r, r * rng.uniform(-0.2, 0.2),
                           r * 1.002 + light_r * 1.001, 0.0, 0.0);
  light["material"] = material(rng, log_uniform(rng, 1.0, 10.0));
  bodies.push_back(light);
  json hammer = random_body(rng, "hammer", r, 0.0, r * 5.0, 0.0, 0.0);
  hammer["material"] = material(rng, heavy);
  hammer["velocity"] = {0.0, -std::sqrt(g * r) * rng.uniform(1.0, 30.0)};
  bodies.push_back(hammer);
}

}  // namespace

StressScene random_stress_scene(std::uint64_t seed) {
  Rng rng(derive_seed(seed, 0x5157e55));
  StressScene s;
  s.seed = seed;
  s.scale = log_uniform(rng, 1e-3, 100.0);
  static const std::array<std::string, 4> kinds = {"loose", "stack", "swarm", "squeeze"};
  s.kind = pick(rng, kinds);
  static const std::array<std::string, 3> presets = {"draft", "normal", "precise"};
  const std::string& accuracy = pick(rng, presets);
  // A bound on steps: 600 of the preset's longest step (4, 1 or 0.25 ms).
  const double max_step = accuracy == "draft" ? 4e-3 : accuracy == "normal" ? 1e-3 : 2.5e-4;
  json world = {{"duration", 600.0 * max_step},
                {"seed", seed},
                {"accuracy", accuracy},
                {"q", rng.uniform(0.1, 1.0)},
                {"friction_gain", rng.uniform() < 0.2 ? 0.0 : log_uniform(rng, 0.1, 1e4)}};
  // Resting contact by micro-collisions alone (mid_step_rest 0, the presets' model before
  // mid-step rest) for a quarter of the scenes, half of those without rest steps too; and
  // mid-step solves cut to 4 sweeps for an eighth, so that unconverged solves are common; the
  // step-independent contact rules (converging_contacts 1) for another eighth, and the soft
  // resting solve (soft_rest 8) for another. Drawn
  // from a stream of its own, so that a seed's other draws stay what they were.
  Rng knob_rng(derive_seed(seed, 0x3e57));
  const double knob_draw = knob_rng.uniform();
  if (knob_draw < 0.25) {
    json knobs = {{"preset", accuracy}, {"mid_step_rest", 0}};
    if (knob_rng.uniform() < 0.5) knobs["rest_stride"] = 1;
    world["accuracy"] = knobs;
  } else if (knob_draw < 0.375) {
    world["accuracy"] = {{"preset", accuracy}, {"rest_sweeps", 4}};
  } else if (knob_draw < 0.5) {
    world["accuracy"] = {{"preset", accuracy}, {"converging_contacts", 1}};
  } else if (knob_draw < 0.625) {
    world["accuracy"] = {{"preset", accuracy}, {"soft_rest", 8}};
  }
  json bodies = json::array();
  if (s.kind == "loose") loose(rng, s, bodies);
  if (s.kind == "stack") stack(rng, s, bodies);
  if (s.kind == "swarm") swarm(rng, s, bodies, world);
  if (s.kind == "squeeze") squeeze(rng, s, bodies, world);
  s.scene = {{"version", 1},
             {"name", numbered("stress_", static_cast<int>(seed % 1000000000))},
             {"world", world},
             {"bodies", bodies}};
  return s;
}

}  // namespace rugosim::testing
