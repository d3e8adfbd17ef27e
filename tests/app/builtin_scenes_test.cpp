// The built-in scenes (scenes/) through the rugosim program: each validates and simulates, and
// the validation scenes reproduce their closed forms in the CSV the program wrote.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "support/program_under_test.h"

namespace {

namespace fs = std::filesystem;

using rugosim::testing::program;
using rugosim::testing::source_dir;

fs::path scratch() {
  const fs::path dir =
      fs::temp_directory_path() / ("rugosim_app_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

// Removes the scratch folder when the program's tests end.
class ScratchCleanup : public ::testing::Environment {
 public:
  void TearDown() override { fs::remove_all(scratch()); }
};
const ::testing::Environment* const kCleanup =
    ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

// Runs the program with `args`, stdout and stderr discarded; returns its exit code.
int run(const std::string& args) {
  const int status = std::system((program() + " " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// trajectory.csv as columns of one body: name -> column -> values in frame order.
std::map<std::string, std::vector<double>> body_columns(const fs::path& csv,
                                                        const std::string& body) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::istringstream header(line);
  for (std::string name; std::getline(header, name, ',');)
    names.push_back(name);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::vector<std::string> fields;
    for (std::string f; std::getline(row, f, ',');)
      fields.push_back(f);
    if (fields.size() != names.size() || fields[2] != body) continue;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (i != 2) columns[names[i]].push_back(std::strtod(fields[i].c_str(), nullptr));
    }
  }
  return columns;
}

// Simulates scenes/<name>.json with extra options; returns the trajectory path.
fs::path simulate(const std::string& name, const std::string& options = "") {
  const fs::path out = scratch() / (name + ".csv");
  const std::string scene = (source_dir() / "scenes" / (name + ".json")).string();
  EXPECT_EQ(run("simulate " + scene + " --trajectory " + out.string() + " " + options), 0);
  return out;
}

TEST(BuiltinScenes, EveryOneValidatesAndSimulates) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(source_dir() / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    ++count;
    const std::string scene = entry.path().string();
    EXPECT_EQ(run("validate " + scene), 0) << scene;
    const fs::path out = scratch() / (entry.path().stem().string() + "_short.csv");
    EXPECT_EQ(run("simulate " + scene + " --duration 0.5 --trajectory " + out.string()), 0)
        << scene;
    std::ifstream in(out);
    std::string line;
    int lines = 0;
    while (std::getline(in, line))
      ++lines;
    EXPECT_GT(lines, 15) << scene;  // header + 16 frames of every movable body at 30 fps
  }
  EXPECT_GE(count, 13);
}

// v0 = 2 m/s, μ = 0.2: rolls at 2v0/3 (band 0.3 mm: the contact point half a band off the
// surface shifts it by at most 0.04%), at every preset within 0.1%.
TEST(BuiltinScenes, SlidingDiskEndsRollingAtTwoThirdsOfItsSpeed) {
  for (const std::string preset : {"draft", "normal", "precise"}) {
    const auto disk = body_columns(
        simulate("validation_sliding_disk", "--accuracy " + std::string(preset)), "disk");
    const double v = disk.at("vx").back();
    RecordProperty("final_vx_" + std::string(preset), std::to_string(v));
    EXPECT_NEAR(v, 4.0 / 3.0, 1e-3 * 4.0 / 3.0) << preset;
  }
}

// Head-on, no gravity, ε = 0.6 (scenes/validation_two_disks.json): at every preset the disks
// separate at ε times their closing speed, to 1e-6 of it, and each leaves with the velocity that
// keeps momentum, within 2e-3 of the closing speed (the masses here are π·r²·ρ; the B-spline
// outlines' own differ from them by less than 0.1%).
TEST(BuiltinScenes, TwoDisksLeaveTheirHeadOnCollisionAsMomentumAndRestitutionSay) {
  const double ma = std::numbers::pi * 0.2 * 0.2 * 1000.0;
  const double mb = std::numbers::pi * 0.15 * 0.15 * 3000.0;
  const double va = 2.0, vb = -1.0, epsilon = 0.6, closing = va - vb;
  const double momentum = ma * va + mb * vb;
  for (const std::string preset : {"draft", "normal", "precise"}) {
    const fs::path run = simulate("validation_two_disks", "--accuracy " + preset);
    const double light = body_columns(run, "light").at("vx").back();
    const double heavy = body_columns(run, "heavy").at("vx").back();
    EXPECT_NEAR((light - heavy) / closing, -epsilon, 1e-6) << preset;
    EXPECT_NEAR(light, (momentum - mb * epsilon * closing) / (ma + mb), 2e-3 * closing) << preset;
    EXPECT_NEAR(heavy, (momentum + ma * epsilon * closing) / (ma + mb), 2e-3 * closing) << preset;
  }
}

// tan θ = 0.3 < μ = 0.5: the block stays (its release hop moves it about 2 mm).
TEST(BuiltinScenes, BlockStaysOnInclineBelowTheFrictionAngle) {
  const auto block = body_columns(simulate("validation_incline_below"), "block");
  const double moved = block.at("x").back() - block.at("x").front();
  RecordProperty("displacement", std::to_string(moved));
  EXPECT_LT(std::abs(moved), 8e-3);
  EXPECT_LT(std::abs(block.at("vx").back()), 1e-2);
}

// tan θ = 0.7 > μ = 0.5: a = g(sin θ − μ cos θ), fitted to x over [0.1, 1.2] s at 100 fps.
TEST(BuiltinScenes, BlockSlidesDownInclineAboveTheFrictionAngle) {
  const auto block = body_columns(simulate("validation_incline_above", "--fps 100"), "block");
  // Least squares of x = c0 + c1·t + ½·a·t² (normal equations, 3 x 3).
  double m[3][4] = {};
  for (std::size_t i = 0; i < block.at("time").size(); ++i) {
    const double t = block.at("time")[i];
    if (t < 0.1) continue;
    const double phi[3] = {1.0, t, 0.5 * t * t};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        m[r][c] += phi[r] * phi[c];
      m[r][3] += phi[r] * block.at("x")[i];
    }
  }
  for (int c = 0; c < 3; ++c) {
    for (int r = c + 1; r < 3; ++r) {
      const double f = m[r][c] / m[c][c];
      for (int k = c; k < 4; ++k)
        m[r][k] -= f * m[c][k];
    }
  }
  const double a = m[2][3] / m[2][2];
  const double theta = std::atan(0.7);
  const double expected = 9.81 * (std::sin(theta) - 0.5 * std::cos(theta));
  RecordProperty("a", std::to_string(a));
  EXPECT_NEAR(a, expected, 0.01 * expected);
}

// ε = 0.5, μ = 0: apex heights above the floor fall by ε² = 0.25 per bounce. Apexes from the
// frames (1 kHz) where v_y turns positive: y + v_y²/(2g) − r.
TEST(BuiltinScenes, BouncingDiskApexesFallByRestitutionSquared) {
  const auto disk = body_columns(simulate("validation_bouncing_disk", "--fps 1000"), "disk");
  const std::vector<double>& y = disk.at("y");
  const std::vector<double>& vy = disk.at("vy");
  std::vector<double> apexes = {0.75};
  for (std::size_t i = 1; i < vy.size(); ++i) {
    if (vy[i - 1] < 0.0 && vy[i] > 0.0) apexes.push_back(y[i] + vy[i] * vy[i] / (2 * 9.81) - 0.25);
  }
  ASSERT_GE(apexes.size(), 4u);
  for (std::size_t i = 1; i < 4; ++i)
    EXPECT_NEAR(apexes[i] / apexes[i - 1], 0.25, 1e-3) << "bounce " << i;
}

// v0 = 3 m/s onto a patch of μ = 0.5: d = v0²/(2gμ) = 0.917 m. The block's centre stops
// within d of the patch's start, its front edge no further than d plus its length.
TEST(BuiltinScenes, RoughPatchStopsTheBlockWithinTheClosedFormDistance) {
  const auto block = body_columns(simulate("validation_rough_patch"), "block");
  const double centre = block.at("x").back();
  const double d = 9.0 / (2.0 * 9.81 * 0.5);
  RecordProperty("centre_stop", std::to_string(centre));
  EXPECT_LT(centre, d);
  EXPECT_GT(centre + 0.2, d - 0.06);      // the front edge reaches d, less a segment
  EXPECT_EQ(block.at("vx").back(), 0.0);  // asleep
}

}  // namespace
