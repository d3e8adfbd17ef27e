// Accepted crossings said out loud (render/app/crossing_report.h): a run whose knobs are too
// coarse to back off before contact (10 ms steps, one bisection, a time-of-impact tolerance as
// long as the step: a disk at rest a little above the floor crosses it at every trial, and
// stopping it does not help) accepts crossing states through its fallback. simulate then warns on
// stderr at the first one (time, bodies, depth), records it in stats.json, and with --strict exits
// 1 after writing its files; render and snapshot do the same. A clean run says nothing and
// --strict keeps exit 0.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/program_under_test.h"

namespace {

namespace fs = std::filesystem;
using rugosim::testing::program;
using rugosim::testing::source_dir;

// Micro-collisions alone: with the presets' mid-step rest the disk stops on the floor before any
// step can carry it through, and nothing crosses even at these knobs.
const std::string kCoarse =
    " --max-step 0.01 --max-bisections 1 --toi-tolerance 0.01 --mid-step-rest 0";

class CrossingReport : public ::testing::Test {
 protected:
  // Runs `rugosim ARGS`; the exit code, stderr in err_.
  int run(const std::string& args) {
    const rugosim::testing::CommandRun r =
        rugosim::testing::run_command_line(program() + " " + args, dir_ / "stderr.txt");
    err_ = r.stderr_text;
    return r.exit_code;
  }
  std::string scene(const std::string& name) const {
    return (source_dir() / "scenes" / (name + ".json")).string();
  }
  nlohmann::json stats() const {
    std::ifstream in(dir_ / "stats.json");
    return nlohmann::json::parse(in);
  }

  rugosim::testing::ScratchDir scratch_{"crossings"};
  const fs::path& dir_ = scratch_.path();
  std::string err_;
};

TEST_F(CrossingReport, SimulateWarnsAtTheFirstAndStrictExits1AfterWriting) {
  const std::string args = "simulate " + scene("validation_bouncing_disk") + kCoarse + " --stats " +
                           (dir_ / "stats.json").string();
  ASSERT_EQ(run(args), 0) << err_;
  EXPECT_NE(err_.find("warning: t = "), std::string::npos) << err_;
  EXPECT_NE(err_.find("bodies \"floor\" and \"disk\" cross"), std::string::npos) << err_;
  EXPECT_NE(err_.find(" m deep"), std::string::npos) << err_;
  const nlohmann::json s = stats();
  ASSERT_GT(s.at("crossings").get<int>(), 0);
  const nlohmann::json& first = s.at("first_crossing");
  EXPECT_EQ(first.at("body_a"), "floor");
  EXPECT_EQ(first.at("body_b"), "disk");
  EXPECT_GT(first.at("time").get<double>(), 0.0);
  // The disk is in a band of millimetres: a crossing accepted at contact is shallow.
  EXPECT_GT(first.at("depth").get<double>(), 0.0);
  EXPECT_LT(first.at("depth").get<double>(), 0.01);
  // The warning comes once, however many states cross.
  EXPECT_EQ(err_.find("warning:"), err_.rfind("warning:"));

  fs::remove(dir_ / "stats.json");
  EXPECT_EQ(run(args + " --strict"), 1) << err_;
  EXPECT_NE(err_.find("error: --strict: "), std::string::npos) << err_;
  EXPECT_TRUE(fs::exists(dir_ / "stats.json"));  // written before the exit code
}

TEST_F(CrossingReport, RenderStrictExits1) {
  const std::string args = "render " + scene("validation_bouncing_disk") + kCoarse +
                           " --size 64x64 -y -o " + (dir_ / "clip.mp4").string();
  EXPECT_EQ(run(args), 0) << err_;
  EXPECT_NE(err_.find("warning: t = "), std::string::npos) << err_;
  EXPECT_EQ(run(args + " --strict"), 1) << err_;
  EXPECT_TRUE(fs::exists(dir_ / "clip.mp4"));
}

TEST_F(CrossingReport, SnapshotWarnsAndStrictExits1AfterWritingTheGoldens) {
  const std::string args = "snapshot " + scene("validation_bouncing_disk") + kCoarse +
                           " --size 64x64 --frames 0,30 --update --golden " +
                           (dir_ / "goldens").string();
  EXPECT_EQ(run(args), 0) << err_;
  EXPECT_NE(err_.find("warning: t = "), std::string::npos) << err_;
  EXPECT_EQ(run(args + " --strict"), 1) << err_;
  EXPECT_NE(err_.find("error: --strict: "), std::string::npos) << err_;
  EXPECT_TRUE(fs::exists(dir_ / "goldens" / "validation_bouncing_disk_30.png"));
  // Comparing against those goldens passes, and still fails with --strict.
  const std::string compare = "snapshot " + scene("validation_bouncing_disk") + kCoarse +
                              " --golden " + (dir_ / "goldens").string();
  EXPECT_EQ(run(compare), 0) << err_;
  EXPECT_EQ(run(compare + " --strict"), 1) << err_;
}

TEST_F(CrossingReport, ACleanRunSaysNothingAndStrictKeepsExit0) {
  ASSERT_EQ(run("simulate " + scene("validation_bouncing_disk") + " --strict --stats " +
                (dir_ / "stats.json").string()),
            0)
      << err_;
  EXPECT_EQ(err_.find("warning"), std::string::npos) << err_;
  EXPECT_EQ(stats().at("crossings"), 0);
  EXPECT_FALSE(stats().contains("first_crossing"));
}

}  // namespace
