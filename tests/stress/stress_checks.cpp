#include "stress_checks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace rugosim::testing {
namespace {

bool parse_double(std::string_view field, double* out) {
  // from_chars reads "nan" and "inf" too: those are what the check must catch, so keep them.
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), *out);
  return ec == std::errc() && end == field.data() + field.size();
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

const nlohmann::json* find_body(const nlohmann::json& scene, const std::string& name) {
  for (const auto& b : scene.at("bodies")) {
    if (b.value("name", "") == name && b.value("fixed", false) && b.at("shape").contains("box") &&
        b.value("angle", 0.0) == 0.0) {
      return &b;
    }
  }
  return nullptr;
}

std::string number(double v) {
  std::ostringstream text;
  text.precision(6);
  text << v;
  return text.str();
}

}  // namespace

std::optional<std::vector<TrajectoryRow>> read_trajectory(const std::string& text,
                                                          std::string* error) {
  std::vector<TrajectoryRow> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);  // header
  long number_of_line = 1;
  while (std::getline(in, line)) {
    ++number_of_line;
    const auto f = split(line);
    TrajectoryRow r;
    double frame = 0.0;
    bool ok = f.size() == 10 && parse_double(f[0], &frame) && parse_double(f[1], &r.time) &&
              parse_double(f[3], &r.x) && parse_double(f[4], &r.y) &&
              parse_double(f[5], &r.angle) && parse_double(f[6], &r.vx) &&
              parse_double(f[7], &r.vy) && parse_double(f[8], &r.omega) &&
              parse_double(f[9], &r.kinetic_energy);
    if (!ok) {
      *error = "trajectory.csv line " + std::to_string(number_of_line) + " unreadable: " + line;
      return std::nullopt;
    }
    r.frame = static_cast<long>(frame);
    r.body = std::string(f[2]);
    rows.push_back(std::move(r));
  }
  return rows;
}

std::optional<InnerBox> closed_container(const nlohmann::json& scene) {
  const auto* floor = find_body(scene, "floor");
  const auto* ceiling = find_body(scene, "ceiling");
  const auto* left = find_body(scene, "left_wall");
  const auto* right = find_body(scene, "right_wall");
  if (floor == nullptr || ceiling == nullptr || left == nullptr || right == nullptr) {
    return std::nullopt;
  }
  const auto face = [](const nlohmann::json& b, std::size_t axis, double side) {
    return b.at("position")[axis].get<double>() +
           side * 0.5 * b.at("shape").at("box").at("size")[axis].get<double>();
  };
  return InnerBox{face(*left, 0u, 1.0), face(*floor, 1u, 1.0), face(*right, 0u, -1.0),
                  face(*ceiling, 1u, -1.0)};
}

std::vector<std::string> check_run(const std::vector<TrajectoryRow>& rows,
                                   const std::map<std::string, double>& masses,
                                   const double gravity[2], double scene_height,
                                   const std::optional<InnerBox>& box,
                                   const nlohmann::json& stats) {
  std::vector<std::string> failures;
  if (stats.value("crossings", std::uint64_t{1}) != 0) {
    failures.push_back("accepted crossings: " + stats.at("crossings").dump() +
                       " (first: " + stats.value("first_crossing", nlohmann::json()).dump() + ")");
  }
  // Energy per frame, and the scene's scale of energy.
  std::map<long, double> energy;
  double y_lo = std::numeric_limits<double>::infinity(), y_hi = -y_lo;
  double total_mass_weight = 0.0;
  double kinetic0 = 0.0;
  bool all_finite = true;
  for (const TrajectoryRow& r : rows) {
    const double values[] = {r.time, r.x, r.y, r.angle, r.vx, r.vy, r.omega, r.kinetic_energy};
    if (!std::all_of(std::begin(values), std::end(values),
                     [](double v) { return std::isfinite(v); })) {
      if (all_finite) {
        failures.push_back("non-finite state of " + r.body + " at frame " +
                           std::to_string(r.frame));
      }
      all_finite = false;
      continue;
    }
    const auto m = masses.find(r.body);
    if (m == masses.end()) {
      failures.push_back("trajectory names an unknown body: " + r.body);
      return failures;
    }
    energy[r.frame] += r.kinetic_energy - m->second * (gravity[0] * r.x + gravity[1] * r.y);
    if (r.frame == 0) {
      kinetic0 += r.kinetic_energy;
      y_lo = std::min(y_lo, r.y);
      y_hi = std::max(y_hi, r.y);
      total_mass_weight += m->second * std::hypot(gravity[0], gravity[1]);
    }
    if (box && !(r.x >= box->x0 && r.x <= box->x1 && r.y >= box->y0 && r.y <= box->y1)) {
      failures.push_back("body " + r.body + " left its closed container at t = " + number(r.time) +
                         " (centre at " + number(r.x) + ", " + number(r.y) + ")");
      return failures;
    }
  }
  if (!all_finite || energy.empty()) return failures;
  const double height = std::max(y_hi - y_lo, scene_height);
  const double scale = kinetic0 + total_mass_weight * height;
  const double start = energy.begin()->second;
  for (const auto& [frame, e] : energy) {
    if (e > start + kEnergyRiseTolerance * scale) {
      failures.push_back("energy rose from " + number(start) + " to " + number(e) + " J at frame " +
                         std::to_string(frame) + " (tolerance " +
                         number(kEnergyRiseTolerance * scale) + " J)");
      break;
    }
  }
  return failures;
}

}  // namespace rugosim::testing
