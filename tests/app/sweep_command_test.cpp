// `rugosim sweep` as a task engine sees it (commands.h, sweep_task.h): a task runs into its own
// folder atomically and is skipped when done; what a killed run left is cleaned up by the next;
// a folder of another sweep is refused (exit 2) unless -y; --gather refuses an incomplete sweep
// without writing anything, and otherwise writes one CSV row per task and the plots; a bad spec
// or task index exits 2 with nothing written.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/program_under_test.h"

namespace {

namespace fs = std::filesystem;
using rugosim::testing::CommandRun;
using rugosim::testing::program;
using rugosim::testing::run_command_line;
using rugosim::testing::ScratchDir;
using rugosim::testing::source_dir;

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A 2 × 2 sweep of the incline (a short run: 0.3 s) written into `dir`.
fs::path write_spec(const fs::path& dir, double duration = 0.3) {
  const fs::path spec = dir / "small.json";
  std::ofstream(spec) << fmt::format(
      R"j({{"version": 1, "scene": "{}",
          "set": {{"/world/duration": {}}},
          "axes": [{{"name": "gain", "values": [100, 450], "pointer": "/world/friction_gain"}},
                   {{"name": "angle", "values": [10, 45],
                     "set": {{"/world/gravity/0": "9.81 * sin(angle * pi / 180)",
                              "/world/gravity/1": "-9.81 * cos(angle * pi / 180)"}}}}],
          "command": {{"simulate": {{"outputs": ["trajectory", "stats"]}}}},
          "measures": [{{"name": "x_end", "trajectory": {{"body": "block", "column": "x"}}}},
                       {{"name": "steps", "stats": "steps"}},
                       {{"name": "moved", "expression": "x_end > -1.99"}}]}})j",
      (source_dir() / "scenes" / "validation_incline_below.json").string(), duration);
  return spec;
}

class SweepCommand : public ::testing::Test {
 protected:
  SweepCommand() : scratch_("sweep_command"), spec_(write_spec(scratch_.path())) {}

  CommandRun sweep(const std::string& arguments) {
    return run_command_line(
        fmt::format("{} sweep {} -o {} {}", program(), spec_.string(), out().string(), arguments),
        scratch_.path() / "stderr.txt");
  }
  fs::path out() const { return scratch_.path() / "out"; }

  ScratchDir scratch_;
  fs::path spec_;
};

TEST_F(SweepCommand, TasksRunOnceAndGatherIntoOneTable) {
  for (int task = 0; task < 4; ++task)
    ASSERT_EQ(sweep(fmt::format("--task {}", task)).exit_code, 0) << task;
  const fs::path folder = out() / "task_000003";
  for (const char* file : {"scene.json", "trajectory.csv", "stats.json", "result.json"})
    EXPECT_TRUE(fs::exists(folder / file)) << file;
  EXPECT_FALSE(fs::exists(folder / "events.csv"));  // not asked for
  const std::string result = read(folder / "result.json");
  EXPECT_NE(result.find("\"angle\": 45"), std::string::npos) << result;

  // Done: a rerun leaves the result as it was.
  const auto written = fs::last_write_time(folder / "result.json");
  const CommandRun again = sweep("--task 3");
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_EQ(fs::last_write_time(folder / "result.json"), written);

  ASSERT_EQ(sweep("--gather").exit_code, 0);
  const std::string csv = read(out() / "sweep.csv");
  std::istringstream lines(csv);
  std::string header, row;
  std::getline(lines, header);
  EXPECT_EQ(header, "task,gain,angle,x_end,steps,moved");
  int rows = 0;
  while (std::getline(lines, row))
    ++rows;
  EXPECT_EQ(rows, 4);
  // Every row: task, gain, angle, x_end, steps, moved. The block slides at 45° with μ = 0.2
  // (and 0.9 < tan 45°), and stays at 10°.
  std::istringstream table(csv);
  std::getline(table, row);
  for (const char* expected : {"0,100,10,", "1,100,45,", "2,450,10,", "3,450,45,"}) {
    ASSERT_TRUE(std::getline(table, row));
    EXPECT_EQ(row.rfind(expected, 0), 0u) << row;
    const bool slides = row.find(",45,") != std::string::npos;
    EXPECT_EQ(row.substr(row.size() - 2), slides ? ",1" : ",0") << row;
  }
  for (const char* plot :
       {"x_end_vs_gain.png", "x_end_vs_angle.png", "x_end_map.png", "moved_map.png"})
    EXPECT_GT(fs::file_size(out() / "plots" / plot), 1000u) << plot;
}

TEST_F(SweepCommand, AKilledRunIsCleanedUpAndRedone) {
  ASSERT_EQ(sweep("--task 0").exit_code, 0);
  // What a run killed half-way leaves: a partial folder of a process that is gone (pid 1 is
  // alive, so use a pid that cannot be: above the kernel's pid_max).
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  std::string name = host;
  for (char& c : name) {
    if (c == '-' || c == '/' || c == '.') c = '_';
  }
  const fs::path partial = out() / fmt::format(".task_000001.partial-{}-99999999", name);
  fs::create_directories(partial);
  std::ofstream(partial / "trajectory.csv") << "frame,time,body\n0,0,blo";
  // A run of another machine is not ours to remove.
  const fs::path elsewhere = out() / ".task_000001.partial-elsewhere-12";
  fs::create_directories(elsewhere);

  const CommandRun gather = sweep("--gather");
  EXPECT_EQ(gather.exit_code, 1);
  EXPECT_NE(gather.stderr_text.find("3 of 4 tasks"), std::string::npos) << gather.stderr_text;
  EXPECT_FALSE(fs::exists(out() / "sweep.csv"));

  const CommandRun run = sweep("--task 1");
  EXPECT_EQ(run.exit_code, 0) << run.stderr_text;
  EXPECT_NE(run.stderr_text.find("that was stopped"), std::string::npos) << run.stderr_text;
  EXPECT_FALSE(fs::exists(partial));
  EXPECT_TRUE(fs::exists(elsewhere));
  EXPECT_TRUE(fs::exists(out() / "task_000001" / "result.json"));
}

// A retried container repeats its host name and often its pid: a partial folder named with the
// new run's own pid is an old run's, never reused (its files would slip into the result).
TEST_F(SweepCommand, APartialFolderWithTheRunsOwnPidIsNotReused) {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  std::string name = host;
  for (char& c : name) {
    if (c == '-' || c == '/' || c == '.') c = '_';
  }
  // bash makes the folder with its own pid, then becomes rugosim (exec keeps the pid).
  const std::string script = fmt::format(
      "mkdir -p {0}/.task_000000.partial-{1}-$$ && touch {0}/.task_000000.partial-{1}-$$/STALE && "
      "exec {2} sweep {3} -o {0} --task 0",
      out().string(), name, program(), spec_.string());
  const CommandRun run =
      run_command_line("bash -c '" + script + "'", scratch_.path() / "stderr.txt");
  EXPECT_EQ(run.exit_code, 0) << run.stderr_text;
  EXPECT_TRUE(fs::exists(out() / "task_000000" / "result.json"));
  EXPECT_FALSE(fs::exists(out() / "task_000000" / "STALE"));
}

TEST_F(SweepCommand, AnotherSweepsFolderIsRefusedUnlessForced) {
  ASSERT_EQ(sweep("--task 2").exit_code, 0);
  write_spec(scratch_.path(), 0.4);  // the spec changed: its results are another sweep's
  const CommandRun refused = sweep("--task 2");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.stderr_text.find("the result of another sweep"), std::string::npos)
      << refused.stderr_text;
  const CommandRun forced = sweep("--task 2 -y");
  EXPECT_EQ(forced.exit_code, 0) << forced.stderr_text;
  const nlohmann::json scene = nlohmann::json::parse(read(out() / "task_000002" / "scene.json"));
  EXPECT_EQ(scene["world"]["duration"], nlohmann::json(0.4));
}

TEST_F(SweepCommand, BadSpecsAndIndicesExit2WritingNothing) {
  const CommandRun range = sweep("--task 4");
  EXPECT_EQ(range.exit_code, 2);
  EXPECT_NE(range.stderr_text.find("the sweep has 4 tasks (0 to 3)"), std::string::npos);
  EXPECT_EQ(sweep("--task x").exit_code, 2);
  const CommandRun none = sweep("");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(sweep("--list --gather").exit_code, 2);
  ::unsetenv("SLURM_ARRAY_TASK_ID");
  ::unsetenv("JOB_COMPLETION_INDEX");
  ::unsetenv("PARALLEL_SEQ");
  const CommandRun no_engine = sweep("--task auto");
  EXPECT_EQ(no_engine.exit_code, 2);
  EXPECT_NE(no_engine.stderr_text.find("--task auto: none of SLURM_ARRAY_TASK_ID"),
            std::string::npos);
  EXPECT_EQ(run_command_line(fmt::format("env PARALLEL_SEQ=2 {} sweep {} -o {} --task auto",
                                         program(), spec_.string(), out().string()),
                             scratch_.path() / "stderr.txt")
                .exit_code,
            0);
  EXPECT_TRUE(fs::exists(out() / "task_000001" / "result.json"));  // PARALLEL_SEQ is 1-based

  std::ofstream(spec_) << R"({"version": 1, "scene": "nowhere.json", "axes": [],
                              "command": {"simulate": {}}, "mesures": []})";
  fs::remove_all(out());
  const CommandRun bad = sweep("--task 0");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.stderr_text.find(R"(/mesures: unknown key "mesures"; did you mean "measures"?)"),
            std::string::npos)
      << bad.stderr_text;
  EXPECT_NE(bad.stderr_text.find("/scene: cannot read the scene file"), std::string::npos);
  EXPECT_FALSE(fs::exists(out()));
}

}  // namespace
