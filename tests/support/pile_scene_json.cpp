#include "support/pile_scene_json.h"

#include <fmt/core.h>

#include "engine/core/random.h"

namespace rugosim::testing {
namespace {

std::string number(double x) {
  return fmt::format("{}", x);
}

std::string pair(const Vec2& v) {
  return fmt::format("[{}, {}]", v.x(), v.y());
}

}  // namespace

std::string pile_scene_json(const PileSpec& spec, const std::string& name, double duration) {
  const std::vector<PileBody> bodies = pile_scene(spec);
  std::string out = fmt::format(
      "// {} irregular rocks ({} segments, sigma = {} m, seeded outlines, angles and small\n"
      "// velocities) dropped in rows into an open box: the pile of bench_pile, written by\n"
      "// tests/support/make_pile_scenes.cpp (do not edit: regenerate it).\n"
      "{{\n"
      "  \"version\": 1,\n"
      "  \"name\": \"{}\",\n"
      "  \"world\": {{ \"duration\": {}, \"seed\": {} }},\n"
      "  \"materials\": {{\n"
      "    \"rock\": {{ \"density\": {}, \"restitution\": {}, \"restitution_max\": {}, "
      "\"lambda_min\": 0 }}\n"
      "  }},\n"
      "  \"bodies\": [\n",
      spec.bodies, spec.segments, number(spec.sigma), name, number(duration), spec.seed,
      number(spec.density), number(spec.restitution), number(spec.restitution_max));
  const std::size_t walls = 3;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBodyDesc& d = bodies[i].desc;
    std::string shape;
    if (i < walls) {
      // The walls are sharp boxes centred on their position (pile_scene.cpp).
      shape = fmt::format("{{ \"box\": {{ \"size\": {}, \"segments\": {} }} }}",
                          pair(bodies[i].box_size), d.control_points.size());
    } else {
      const std::size_t k = i - walls;
      shape = fmt::format(
          "{{ \"blob\": {{ \"radius\": {}, \"irregularity\": {}, \"segments\": {}, \"seed\": {} "
          "}} }}",
          number(spec.radius), number(spec.irregularity), spec.segments, derive_seed(spec.seed, k));
    }
    out += fmt::format("    {{ \"name\": \"{}\", {}\"shape\": {}, \"position\": {}", bodies[i].name,
                       d.fixed ? "\"fixed\": true, " : "", shape, pair(d.position));
    if (!d.fixed) {
      out += fmt::format(", \"angle\": {}, \"velocity\": {}, \"angular_velocity\": {}",
                         number(d.angle), pair(d.velocity), number(d.angular_velocity));
    }
    out += fmt::format(", \"material\": \"rock\", \"rugosity\": {{ \"sigma\": {} }} }}{}\n",
                       number(spec.sigma), i + 1 < bodies.size() ? "," : "");
  }
  out +=
      "  ],\n"
      "  \"render\": { \"size\": [1280, 720], \"fps\": 30, \"camera\": \"auto\", \"overlays\": [] "
      "}\n"
      "}\n";
  return out;
}

}  // namespace rugosim::testing
