#include "engine/dynamics/telemetry.h"

#include <array>
#include <charconv>
#include <cstdint>
#include <system_error>

#include <nlohmann/json.hpp>

namespace rugosim {
namespace {

void append_integer(std::string& out, std::uint64_t n) {
  std::array<char, 24> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), n);
  out.append(buffer.data(), result.ptr);
}

}  // namespace

void append_number(std::string& out, double x) {
  // 32 characters hold the longest shortest form of a double ("-2.2250738585072014e-308").
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  out.append(buffer.data(), result.ptr);
}

void append_csv_field(std::string& out, std::string_view field) {
  if (field.find_first_of(",\"\n\r") == std::string_view::npos) {
    out.append(field);
    return;
  }
  out.push_back('"');
  for (const char c : field) {
    if (c == '"') out.push_back('"');
    out.push_back(c);
  }
  out.push_back('"');
}

void append_trajectory_rows(std::string& out, const World& world, std::size_t frame) {
  for (std::size_t i = 0; i < world.body_count(); ++i) {
    const RigidBody& body = world.body(i);
    if (body.fixed()) continue;
    const BodyState& s = body.state();
    append_integer(out, frame);
    out.push_back(',');
    append_number(out, world.time());
    out.push_back(',');
    append_csv_field(out, world.name(i));
    for (const double value : {s.position.x(), s.position.y(), s.angle, s.velocity.x(),
                               s.velocity.y(), s.angular_velocity, body.kinetic_energy()}) {
      out.push_back(',');
      append_number(out, value);
    }
    out.push_back('\n');
  }
}

void append_event_row(std::string& out, const World& world, const ContactEvent& e) {
  append_number(out, e.time);
  out.push_back(',');
  out.append(to_string(e.kind));
  out.push_back(',');
  append_csv_field(out, world.name(e.body_a));
  out.push_back(',');
  append_csv_field(out, world.name(e.body_b));
  out.push_back(',');
  append_integer(out, e.segment_a);
  out.push_back(',');
  append_integer(out, e.segment_b);
  for (const double value : {e.t_a, e.t_b, e.point.x(), e.point.y(), e.normal.x(), e.normal.y(),
                             e.lambda_a, e.lambda_b, e.mu, e.vn, e.vt, e.jn, e.jt}) {
    out.push_back(',');
    append_number(out, value);
  }
  out.push_back('\n');
}

std::string stats_json(const StepStats& s, double wall_time, const Accuracy* accuracy,
                       const World* world) {
  std::string out = "{\n";
  auto counter = [&](std::string_view key, std::uint64_t value) {
    out.append("  \"").append(key).append("\": ");
    append_integer(out, value);
    out.append(",\n");
  };
  counter("steps", s.steps);
  counter("bisections", s.bisections);
  counter("collisions", s.collisions);
  counter("contacts", s.contacts);
  counter("fallbacks", s.fallbacks);
  counter("min_step_fallbacks", s.min_step_fallbacks);
  counter("pass_fallbacks", s.pass_fallbacks);
  counter("rigid_clusters", s.rigid_clusters);
  counter("unresolved_states", s.unresolved_states);
  counter("crossing_fallbacks", s.crossing_fallbacks);
  counter("stalled_steps", s.stalled_steps);
  counter("crossings", s.crossings);
  counter("passes", s.passes);
  counter("islands_slept", s.islands_slept);
  counter("islands_woken", s.islands_woken);
  counter("idle_jumps", s.idle_jumps);
  counter("free_steps", s.free_steps);
  counter("rest_steps", s.rest_steps);
  counter("rest_contacts", s.rest_contacts);
  counter("rest_sweeps", s.rest_sweeps);
  counter("rest_unconverged", s.rest_unconverged);
  counter("rest_withdrawn", s.rest_withdrawn);
  counter("soft_rest_retries", s.soft_rest_retries);
  counter("body_steps", s.body_steps);
  out.append("  \"sim_time\": ");
  append_number(out, s.sim_time);
  out.append(",\n  \"wall_time\": ");
  append_number(out, wall_time);
  out.append(",\n  \"stalled_time\": ");
  append_number(out, s.stalled_time);
  if (accuracy != nullptr) {
    out.append(",\n  \"accuracy\": {");
    const char* separator = "";
    for (const AccuracyKnob& knob : accuracy_knobs()) {
      out.append(separator).append("\"").append(knob.key).append("\": ");
      append_number(out, knob.get(*accuracy));
      separator = ", ";
    }
    out.append("}");
  }
  if (world != nullptr && world->first_crossing()) {
    const CrossingRecord& c = *world->first_crossing();
    out.append(",\n  \"first_crossing\": {\"time\": ");
    append_number(out, c.time);
    out.append(", \"body_a\": ").append(nlohmann::json(world->name(c.body_a)).dump());
    out.append(", \"body_b\": ").append(nlohmann::json(world->name(c.body_b)).dump());
    out.append(", \"depth\": ");
    append_number(out, c.depth);
    out.append("}");
  }
  out.append("\n}\n");
  return out;
}

}  // namespace rugosim
