// The accuracy options through the program: --accuracy replaces the scene's accuracy and each
// knob option overrides one knob, as stats.json reports; a knob out of range, or a time-of-
// impact tolerance above the step, exits 2 and writes nothing.
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/program_under_test.h"

namespace {

namespace fs = std::filesystem;
using rugosim::testing::program;
using rugosim::testing::source_dir;

class AccuracyOptions : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rugosim_accuracy_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Simulates figure06_type1_type1 for 0.2 s with `options`; the exit code.
  int simulate(const std::string& options) const {
    const std::string scene = (source_dir() / "scenes" / "figure06_type1_type1.json").string();
    const std::string command = program() + " simulate " + scene + " --duration 0.2 --stats " +
                                stats().string() + " " + options + " >/dev/null 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  fs::path stats() const { return dir_ / "stats.json"; }
  nlohmann::json accuracy() const {
    std::ifstream in(stats());
    return nlohmann::json::parse(in).at("accuracy");
  }

  fs::path dir_;
};

TEST_F(AccuracyOptions, PresetAndKnobsReachTheRun) {
  ASSERT_EQ(simulate(""), 0);
  EXPECT_EQ(accuracy().at("max_step"), 0.001);  // the scene's preset: normal
  EXPECT_EQ(accuracy().at("seed_depth"), 48);
  ASSERT_EQ(simulate("--accuracy draft"), 0);
  EXPECT_EQ(accuracy().at("max_step"), 0.002);
  EXPECT_EQ(accuracy().at("contact_passes"), 32);
  ASSERT_EQ(simulate("--accuracy precise --max-step 0.0005 --seed-depth 20 --contact-threshold 0"),
            0);
  EXPECT_EQ(accuracy().at("max_step"), 0.0005);
  EXPECT_EQ(accuracy().at("seed_depth"), 20);
  EXPECT_EQ(accuracy().at("contact_threshold"), 0.0);
  EXPECT_EQ(accuracy().at("contact_passes"), 128);  // precise's
}

TEST_F(AccuracyOptions, BadKnobsExit2AndWriteNothing) {
  for (const std::string options :
       {"--max-step 0", "--max-step 2", "--seed-depth 2.5", "--newton-iterations x",
        "--toi-tolerance 0.01", "--accuracy fast", "--contact-threshold -1"}) {
    EXPECT_EQ(simulate(options), 2) << options;
    EXPECT_FALSE(fs::exists(stats())) << options;
  }
}

}  // namespace
