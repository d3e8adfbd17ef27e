// `rugosim info --json` on a built-in scene: the keys of INTERFACE.md, with values that match
// the shapes' closed forms.
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

std::string output_of(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    out.append(buffer, n);
  ::pclose(pipe);
  return out;
}

TEST(InfoCommand, JsonHasTheContractKeysAndTheRightMassProperties) {
  const std::string program = std::getenv("RUGOSIM_PROGRAM");
  const std::string scene =
      std::string(std::getenv("RUGOSIM_SOURCE_DIR")) + "/scenes/validation_sliding_disk.json";
  const nlohmann::json info = nlohmann::json::parse(output_of(program + " info --json " + scene));
  ASSERT_EQ(info["bodies"].size(), 2u);
  for (const auto& body : info["bodies"]) {
    for (const char* key : {"name", "segments", "area", "mass", "centroid", "inertia",
                            "lambda_range", "tree_depth"}) {
      EXPECT_TRUE(body.contains(key)) << key;
    }
  }
  // The block: 8 x 0.4 m, density 1000, sharp corners: exact rectangle.
  const auto& block = info["bodies"][0];
  EXPECT_EQ(block["name"], "block");
  EXPECT_NEAR(block["area"].get<double>(), 3.2, 1e-12);
  EXPECT_NEAR(block["mass"].get<double>(), 3200.0, 1e-9);
  EXPECT_NEAR(block["inertia"].get<double>(), 3200.0 * (64.0 + 0.16) / 12.0, 1e-7);
  EXPECT_NEAR(block["centroid"][1].get<double>(), -0.2, 1e-12);
  // λ = q·σ = 0.9 · 0.333 mm = 0.3 mm everywhere.
  EXPECT_NEAR(block["lambda_range"][0].get<double>(), 0.0003, 1e-16);
  EXPECT_NEAR(block["lambda_range"][1].get<double>(), 0.0003, 1e-16);
  // The disk: 64 segments, r = 0.25: the area falls short of πr² by about 4.3/n⁴ of it.
  const auto& disk = info["bodies"][1];
  EXPECT_EQ(disk["segments"], 64);
  EXPECT_NEAR(disk["area"].get<double>(), std::numbers::pi * 0.0625, 1e-6);
  EXPECT_NEAR(disk["centroid"][0].get<double>(), -3.0, 1e-12);
  EXPECT_GE(disk["tree_depth"].get<int>(), 6);
}

}  // namespace
