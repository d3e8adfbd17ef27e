// Every numeric option of every command against the numbers that used to hang the program,
// run nothing, or print CLI11's bounds with 309 digits: NaN, ±infinity, 0, −1, 1e300, 1e-300
// and a value that overflows its count. Each run either exits 2 with a message in the
// project's words (the option, what was expected) and writes nothing, or, where the value is
// legitimate, does what it says (exit 0). The table is checked against the program's own
// list of options, so a numeric option added later without an entry fails here.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "render/app/command_line.h"
#include "render/app/number_option.h"
#include "support/program_under_test.h"

namespace {

namespace fs = std::filesystem;
using rugosim::testing::CommandRun;
using rugosim::testing::program;
using rugosim::testing::run_command_line;
using rugosim::testing::source_dir;

const std::vector<std::string> kValues = {"nan", "inf",   "-inf",   "0",
                                          "-1",  "1e300", "1e-300", "overflow"};

struct NumericOption {
  std::string command;
  std::string name;
  std::set<std::string> legitimate;  // values of kValues the option accepts (exit 0)
  std::string overflow;              // what "overflow" stands for
};

// A count past 2^64: whole-number options overflow it; durations overflow the frame count or
// the clock (run_length.h) instead.
const std::string kPast64Bits = "18446744073709551616";

std::vector<NumericOption> table() {
  std::vector<NumericOption> rows;
  const std::vector<std::string> knob_commands = {"simulate", "render", "snapshot"};
  for (const std::string& command : knob_commands) {
    rows.push_back({command, "--max-step", {}, "1e309"});
    // 1e-300 is in the knob's range, but no run is that fine: the clock bound refuses it.
    rows.push_back({command, "--toi-tolerance", {}, "1e309"});
    rows.push_back({command, "--max-bisections", {}, kPast64Bits});
    rows.push_back({command, "--newton-tolerance", {}, "1e309"});
    rows.push_back({command, "--newton-iterations", {}, kPast64Bits});
    rows.push_back({command, "--rest-stride", {}, kPast64Bits});
    rows.push_back({command, "--mid-step-rest", {"0"}, kPast64Bits});
    rows.push_back({command, "--converging-contacts", {"0"}, kPast64Bits});
    rows.push_back({command, "--rest-sweeps", {}, kPast64Bits});
    rows.push_back({command, "--soft-rest", {"0"}, kPast64Bits});
    rows.push_back({command, "--soft-rest-hertz", {"1e-300"}, "1e309"});
    rows.push_back({command, "--soft-rest-island", {}, kPast64Bits});
    rows.push_back({command, "--seed-depth", {}, kPast64Bits});
    rows.push_back({command, "--contact-passes", {}, kPast64Bits});
    rows.push_back({command, "--contact-threshold", {"0", "1e-300"}, "1e309"});
    rows.push_back({command, "--threads", {}, kPast64Bits});
  }
  // 3.4e6 s is past the clock of the normal preset and, at 30 fps, past 10^8 frames.
  rows.push_back({"simulate", "--duration", {}, "3.4e6"});
  rows.push_back({"simulate", "--fps", {}, "1e309"});
  rows.push_back({"simulate", "--every", {}, kPast64Bits});
  rows.push_back({"join", "--chunks", {}, kPast64Bits});
  rows.push_back({"sweep", "--threads", {}, kPast64Bits});
  rows.push_back({"render", "--duration", {}, "3.4e6"});
  rows.push_back({"render", "--fps", {}, "1e309"});
  rows.push_back({"render", "--roughness-scale", {"0", "1e-300"}, "1e309"});
  rows.push_back({"render", "--crf", {"0"}, kPast64Bits});
  rows.push_back({"render", "--strip", {}, kPast64Bits});
  rows.push_back({"render", "--frame", {"0"}, kPast64Bits});
  // Without --strip these refuse even a good value, naming themselves and what they expect.
  rows.push_back({"render", "--columns", {}, kPast64Bits});
  rows.push_back({"render", "--gap", {}, kPast64Bits});
  rows.push_back({"render", "--gl-threads", {"0"}, kPast64Bits});
  rows.push_back({"render", "--png-workers", {}, kPast64Bits});
  rows.push_back({"render", "--png-level", {"0"}, kPast64Bits});
  rows.push_back({"snapshot", "--threshold", {"0"}, kPast64Bits});
  rows.push_back({"snapshot", "--max-share", {"0", "1e-300"}, "1e309"});
  return rows;
}

class NumberOptions : public ::testing::Test {
 protected:
  // The command with `option value` and short, small defaults for the rest (a 0.05 s run,
  // 64x64 frames), so that a legitimate value finishes at once.
  std::string command_line(const NumericOption& o, const std::string& value) const {
    const std::string scene = (source_dir() / "scenes" / "validation_bouncing_disk.json").string();
    if (o.command == "join") {
      return program() + " join " + output().string() + " " + o.name + " '" + value + "'";
    }
    if (o.command == "sweep") {  // the sweep's folder is the output that must not appear
      const std::string spec =
          (source_dir() / "scenes" / "sweeps" / "incline_friction.json").string();
      return program() + " sweep " + spec + " --task 0 -o " + output().string() + " " + o.name +
             " '" + value + "'";
    }
    std::string line = program() + " " + o.command + " " + scene;
    const bool sets_duration = o.name == "--duration";
    if (o.command == "simulate") {
      if (!sets_duration) line += " --duration 0.05";
      line += " --stats " + output().string();
    } else if (o.command == "render") {
      if (!sets_duration) line += " --duration 0.05";
      line += " --size 64x64 -y -o " + output(o.name).string();
    } else {
      line += " --size 64x64 --update --golden " + (dir_ / "goldens").string();
    }
    return line + " " + o.name + " '" + value + "'";
  }
  // A clip, or for --frame a still.
  fs::path output(const std::string& option = "") const {
    return dir_ / (option == "--frame" ? "still.png" : "out.mp4");
  }

  rugosim::testing::ScratchDir scratch_{"numbers"};
  const fs::path& dir_ = scratch_.path();
};

// The longest run of decimal digits in `text` (CLI11 wrote DBL_MAX with 309 of them).
std::size_t longest_digit_run(const std::string& text) {
  std::size_t longest = 0, run = 0;
  for (const char ch : text) {
    run = (ch >= '0' && ch <= '9') ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  return longest;
}

TEST_F(NumberOptions, TableCoversEveryNumericOptionOfTheProgram) {
  const auto cli = rugosim::app::make_command_line(2);
  std::set<std::pair<std::string, std::string>> in_program;
  for (const CLI::App* command : cli->app.get_subcommands({})) {
    for (const CLI::Option* option : command->get_options()) {
      const std::string type = option->get_type_name();
      // A number read by CLI11 alone would show its type; every number goes through
      // number_in (or the accuracy knobs' check), which carry a validator of that name.
      EXPECT_TRUE(type != "INT" && type != "UINT" && type != "FLOAT" && type != "NUMBER")
          << command->get_name() << " " << option->get_name() << " is a number CLI11 reads";
      try {
        const_cast<CLI::Option*>(option)->get_validator(rugosim::app::kNumberValidator);
        in_program.insert({command->get_name(), option->get_name(false, true)});
      } catch (const CLI::OptionNotFound&) {
      }
    }
  }
  std::set<std::pair<std::string, std::string>> in_table;
  for (const NumericOption& o : table())
    in_table.insert({o.command, o.name});
  EXPECT_EQ(in_table, in_program);
}

TEST_F(NumberOptions, EveryBadNumberExits2WithAMessageAndWritesNothing) {
  double slowest = 0.0;
  for (const NumericOption& o : table()) {
    for (const std::string& v : kValues) {
      const std::string value = v == "overflow" ? o.overflow : v;
      const std::string line = command_line(o, value);
      fs::remove_all(dir_ / "goldens");
      fs::remove(output(o.name));
      const CommandRun r = run_command_line(line, dir_ / "stderr.txt");
      SCOPED_TRACE(line + "\n" + r.stderr_text);
      if (o.legitimate.count(v) > 0) {
        EXPECT_EQ(r.exit_code, 0);
        continue;
      }
      slowest = std::max(slowest, r.seconds);
      EXPECT_EQ(r.exit_code, 2);
      // The message names the option (or its scene key) and says what was expected.
      std::string key = o.name.substr(2);
      std::replace(key.begin(), key.end(), '-', '_');
      EXPECT_TRUE(r.stderr_text.find(o.name) != std::string::npos ||
                  r.stderr_text.find(key) != std::string::npos);
      EXPECT_TRUE(r.stderr_text.find("expected") != std::string::npos ||
                  r.stderr_text.find("must not exceed") != std::string::npos);
      // Never CLI11's bounds written out digit by digit, nor its "Could not convert".
      std::string without_value = r.stderr_text;
      for (std::size_t at; (at = without_value.find(value)) != std::string::npos;)
        without_value.erase(at, value.size());
      EXPECT_LT(longest_digit_run(without_value), 20u);
      EXPECT_EQ(r.stderr_text.find("Could not convert"), std::string::npos);
      EXPECT_FALSE(fs::exists(output(o.name)));
      EXPECT_FALSE(fs::exists(dir_ / "goldens"));
    }
  }
  // A guard against hangs, not a speed target: each refusal comes before any work.
  EXPECT_LT(slowest, 10.0);
  std::printf("slowest refusal: %.3f s\n", slowest);
}

TEST_F(NumberOptions, CompositeNumbersAreRefusedToo) {
  const std::string scene = (source_dir() / "scenes" / "validation_bouncing_disk.json").string();
  const std::string base = program() + " render " + scene + " -y -o " + output().string() + " ";
  for (const std::string& size : std::vector<std::string>{
           "nanx64", "infx64", "0x0", "-1x64", "1e300x64", "64x1e-300", kPast64Bits + "x64"}) {
    const CommandRun r = run_command_line(base + "--size '" + size + "'", dir_ / "stderr.txt");
    SCOPED_TRACE(size + ": " + r.stderr_text);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.stderr_text.find("size"), std::string::npos);
  }
  for (const std::string& frames : std::vector<std::string>{"0:nan", "inf:5", "0:-1", "0:1e300",
                                                            "1e-300:2", "0:" + kPast64Bits}) {
    const CommandRun r = run_command_line(base + "--frames '" + frames + "'", dir_ / "stderr.txt");
    SCOPED_TRACE(frames + ": " + r.stderr_text);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.stderr_text.find("--frames"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(output()));
}

TEST(NumberOption, ParsesWholeFiniteNumbersOnly) {
  using rugosim::app::parse_number;
  EXPECT_EQ(parse_number("2.5", false), 2.5);
  EXPECT_EQ(parse_number("-1e-3", false), -1e-3);
  EXPECT_EQ(parse_number("12", true), 12.0);
  EXPECT_EQ(parse_number("+7", true), 7.0);
  for (const char* bad : {"", " 1", "1 ", "1x", "nan", "NaN", "inf", "-inf", "1e309", "0x10"}) {
    EXPECT_FALSE(parse_number(bad, false)) << bad;
  }
  for (const char* bad : {"1.0", "1e3", "-", "0x10", "nan", "12a"}) {
    EXPECT_FALSE(parse_number(bad, true)) << bad;
  }
}

TEST(NumberOption, MessageSaysWhatWasExpectedAndWhatWasGiven) {
  const rugosim::app::NumberRange fps{0.0, true, 1000.0, false, false, "frames per second"};
  EXPECT_EQ(rugosim::app::check_number("30", fps), "");
  EXPECT_EQ(rugosim::app::check_number("0", fps),
            "expected a finite number in (0, 1000] (frames per second), got \"0\"");
  EXPECT_EQ(rugosim::app::check_number("1000", fps), "");
  EXPECT_NE(rugosim::app::check_number("1000.0001", fps), "");
}

}  // namespace
