// Touching at t = 0 (issue 15): a crate placed exactly on a floor, and a stack of crates each
// placed where the one below ends (faces at 0 or a rounding across), are valid scenes. Through
// the program at every preset: validate exits 0, simulate --strict exits 0 with no crossing,
// no body moves by more than a pixel of a 1080p view of the scene, and the scene falls asleep.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "stress/stress_checks.h"
#include "support/file_text.h"
#include "support/program_under_test.h"

namespace {

namespace fs = std::filesystem;
using rugosim::testing::program;
using rugosim::testing::run_command_line;
using rugosim::testing::source_dir;

struct Case {
  const char* scene;
  double view_height;  // m: the height a 1080p view of the bodies spans (floor to top crate)
};

class TouchingAtRest : public ::testing::TestWithParam<std::tuple<Case, const char*>> {
 protected:
  rugosim::testing::ScratchDir scratch_{"touching"};
  const fs::path& dir_ = scratch_.path();
};

using rugosim::testing::read_text;

TEST_P(TouchingAtRest, ValidatesRestsBelowAPixelAndSleeps) {
  const auto& [c, accuracy] = GetParam();
  const std::string scene =
      (source_dir() / "tests" / "app" / "crossing_classes" / c.scene).string();
  const auto validate = run_command_line(program() + " validate " + scene, dir_ / "err.txt");
  ASSERT_EQ(validate.exit_code, 0) << validate.stderr_text;

  const fs::path trajectory = dir_ / "trajectory.csv", stats = dir_ / "stats.json";
  const auto sim = run_command_line(program() + " simulate " + scene + " --strict --accuracy " +
                                        accuracy + " --fps 240 --trajectory " +
                                        trajectory.string() + " --stats " + stats.string(),
                                    dir_ / "err.txt");
  ASSERT_EQ(sim.exit_code, 0) << sim.stderr_text;
  const nlohmann::json s = nlohmann::json::parse(read_text(stats));
  EXPECT_EQ(s.at("crossings").get<int>(), 0);
  EXPECT_EQ(s.at("crossing_fallbacks").get<int>(), 0);
  EXPECT_GE(s.at("islands_slept").get<int>(), 1) << "the scene never fell asleep";

  std::string error;
  const auto rows = rugosim::testing::read_trajectory(read_text(trajectory), &error);
  ASSERT_TRUE(rows.has_value()) << error;
  const double pixel = c.view_height / 1080.0;
  std::map<std::string, rugosim::testing::TrajectoryRow> first;
  double worst = 0.0;
  for (const auto& r : *rows) {
    const auto [it, added] = first.emplace(r.body, r);
    const auto& r0 = it->second;
    // A turn moves the crate's corners by the angle times its half-diagonal (at most 0.3 m).
    worst = std::max(
        {worst, std::abs(r.x - r0.x), std::abs(r.y - r0.y), 0.3 * std::abs(r.angle - r0.angle)});
  }
  RecordProperty("largest_move_m", std::to_string(worst));
  EXPECT_LE(worst, pixel) << "a body moved " << worst << " m; a pixel is " << pixel << " m";
}

INSTANTIATE_TEST_SUITE_P(CratesAndStacks, TouchingAtRest,
                         ::testing::Combine(::testing::Values(Case{"crate_on_floor.json", 0.7},
                                                              Case{"crate_stack.json", 1.18}),
                                            ::testing::Values("draft", "normal", "precise")),
                         [](const auto& param_info) {
                           std::string name = std::get<0>(param_info.param).scene;
                           name =
                               name.substr(0, name.find('.')) + "_" + std::get<1>(param_info.param);
                           return name;
                         });

}  // namespace
