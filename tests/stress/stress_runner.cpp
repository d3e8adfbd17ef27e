// The property-based stress suite (issue 15): random valid scenes (random_scene.h), or the kept
// regression scenes, each run through the real program and checked (stress_checks.h):
//   - `validate` accepts it (a refusal is counted with its reason, not a failure);
//   - `simulate --strict` exits 0 within the guard (a hang guard only, never a speed target),
//     with zero accepted crossings, finite states, energy never above its start beyond
//     kEnergyRiseTolerance of the scene's scale, bodies inside their closed container;
//   - a rerun with another number of threads writes the same trajectory, byte for byte;
//   - a run resumed from the checkpoint at frame 15 (simulate --checkpoints, --resume) writes
//     the first run's trajectory rows after that frame, byte for byte, and its stats.json but
//     for wall_time.
//
//   stress_runner --program P (--seeds A:B | --minutes M [--first-seed S] | --scenes DIR)
//                 [--work DIR] [--keep DIR] [--csv FILE] [--guard SECONDS]
//
// Prints one line per scene and a summary (scenes run, refused and why, failures, the slowest
// runs in seconds per simulated second, the spread of cost across scales); exits 1 when any
// scene failed. Failing generated scenes are copied to --keep as seed_N.json, to be kept under
// tests/stress/regressions/.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "random_scene.h"
#include "stress_checks.h"
#include "support/program_under_test.h"

namespace fs = std::filesystem;
using nlohmann::json;
using rugosim::testing::CommandRun;
using rugosim::testing::run_command_line;

namespace {

struct Options {
  std::string program;
  long first = 1, last = 0;  // seeds [first, last]
  double minutes = 0.0;
  fs::path scenes;  // regression mode
  fs::path work = fs::temp_directory_path() / "rugosim_stress";
  fs::path keep;
  fs::path csv;
  int guard = 600;
};

struct Outcome {
  std::string name, kind, accuracy, verdict, reason;
  double scale = 0.0, wall = 0.0, sim = 0.0;
  std::size_t bodies = 0;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string first_line(const std::string& text) {
  const auto end = text.find('\n');
  return text.substr(0, end);
}

std::string shell_quoted(const fs::path& p) {
  // Appended piece by piece: GCC 12's -Wrestrict misreads "'" + std::string once inlined.
  std::string quoted(1, '\'');
  quoted += p.string();
  quoted += '\'';
  return quoted;
}

// The refusal's reason without the file and the numbers, so that equal reasons count together.
std::string reason_class(const std::string& message) {
  std::string out;
  const auto path = message.find(": /");
  std::string text = path == std::string::npos ? message : message.substr(path + 2);
  bool in_number = false;
  for (const char c : text) {
    const bool digit = (c >= '0' && c <= '9') || (in_number && (c == '.' || c == 'e' || c == '-'));
    if (digit && !in_number) out += '#';
    if (!digit) out += c;
    in_number = digit;
  }
  return out.substr(0, 100);
}

double scene_height(const json& scene) {
  double lo = 1e300, hi = -1e300;
  for (const auto& b : scene.at("bodies")) {
    const double y = b.at("position")[1].get<double>();
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  return hi - lo;
}

// The run resumed from its checkpoint at frame 15 (written by the first run): the first run's
// rows after that frame, exactly, and its stats but for wall_time. Nothing to check when the run
// had no frame 15.
void check_resume(const std::string& p, const fs::path& file, const std::string& fps,
                  const fs::path& dir, const std::string& trajectory, int guard,
                  std::vector<std::string>* failures) {
  const fs::path checkpoint = dir / "ck" / "frame_000015.ckpt";
  if (!fs::exists(checkpoint)) return;
  const CommandRun resumed = run_command_line(
      p + " simulate " + shell_quoted(file) + " --strict --fps " + fps + " --threads 2" +
          " --resume " + shell_quoted(checkpoint) + " --trajectory " +
          shell_quoted(dir / "resumed.csv") + " --stats " + shell_quoted(dir / "resumed.json"),
      dir / "resumed.txt", guard);
  if (resumed.exit_code != 0) {
    failures->push_back("simulate --resume exited " + std::to_string(resumed.exit_code) + ": " +
                        first_line(resumed.stderr_text));
    return;
  }
  std::string expected;
  std::istringstream rows(trajectory);
  std::string line;
  std::getline(rows, line);  // the header
  expected = line;
  expected += '\n';
  while (std::getline(rows, line)) {
    if (std::stol(line.substr(0, line.find(','))) <= 15) continue;
    expected += line;
    expected += '\n';
  }
  if (read_text(dir / "resumed.csv") != expected) {
    failures->push_back("the run resumed at frame 15 differs from the whole run after it");
  }
  json whole = json::parse(read_text(dir / "stats1.json"));
  json part = json::parse(read_text(dir / "resumed.json"));
  whole.erase("wall_time");
  part.erase("wall_time");
  if (whole != part)
    failures->push_back("the resumed run's stats.json differs from the whole run's");
}

Outcome run_scene(const Options& o, const json& scene, const std::string& label,
                  std::vector<std::string>* failures) {
  Outcome out;
  out.name = label;
  const json& world = scene.at("world");
  out.accuracy = "normal";
  if (const auto a = world.find("accuracy"); a != world.end() && a->is_string()) {
    out.accuracy = a->get_ref<const std::string&>();
  } else if (a != world.end() && a->is_object()) {
    // A preset with knobs: "normal+mid_step_rest=0+rest_stride=1" (no commas: a CSV cell).
    out.accuracy = a->value("preset", std::string("normal"));
    for (const auto& [key, value] : a->items()) {
      if (key != "preset") out.accuracy += "+" + key + "=" + value.dump();
    }
  }
  out.bodies = scene.at("bodies").size();
  const fs::path dir = o.work / label;
  fs::create_directories(dir);
  const fs::path file = dir / "scene.json";
  std::ofstream(file) << scene.dump(1) << '\n';
  const std::string p = shell_quoted(o.program);

  const CommandRun validate =
      run_command_line(p + " validate " + shell_quoted(file), dir / "validate.txt", o.guard);
  if (validate.exit_code == 2) {
    out.verdict = "refused";
    out.reason = reason_class(first_line(validate.stderr_text));
    return out;
  }
  if (validate.exit_code != 0) {
    failures->push_back("validate exited " + std::to_string(validate.exit_code) + ": " +
                        first_line(validate.stderr_text));
  }
  std::map<std::string, double> masses;
  if (std::system((p + " info " + shell_quoted(file) + " --json >" +
                   shell_quoted(dir / "info.json") + " 2>/dev/null")
                      .c_str()) == 0) {
    const json info = json::parse(read_text(dir / "info.json"));
    for (const auto& b : info.at("bodies"))
      masses[b.at("name").get<std::string>()] = b.at("mass").get<double>();
  }
  const double duration = world.at("duration").get<double>();
  const std::string fps = std::to_string(std::max(1.0, std::round(30.0 / duration)));
  std::string trajectories[2];
  for (int run = 0; run < 2; ++run) {
    const std::string n = std::to_string(run + 1);
    const CommandRun sim = run_command_line(
        p + " simulate " + shell_quoted(file) + " --strict --fps " + fps + " --threads " + n +
            " --trajectory " + shell_quoted(dir / ("trajectory" + n + ".csv")) + " --stats " +
            shell_quoted(dir / ("stats" + n + ".json")) +
            (run == 0 ? " --checkpoints " + shell_quoted(dir / "ck") + " --every 15" : ""),
        dir / ("simulate" + n + ".txt"), o.guard);
    if (run == 0) out.wall = sim.seconds;
    if (sim.exit_code == 124) {
      failures->push_back("simulate --threads " + n + " still running after the " +
                          std::to_string(o.guard) + " s guard");
      return out;
    }
    if (sim.exit_code != 0) {
      failures->push_back("simulate --threads " + n + " exited " + std::to_string(sim.exit_code) +
                          ": " + first_line(sim.stderr_text));
    }
    trajectories[run] = read_text(dir / ("trajectory" + n + ".csv"));
    if (run == 1) break;
    std::string error;
    const auto rows = rugosim::testing::read_trajectory(trajectories[0], &error);
    if (!rows) {
      failures->push_back(error);
      return out;
    }
    json stats;
    try {
      stats = json::parse(read_text(dir / "stats1.json"));
    } catch (const json::exception& e) {
      failures->push_back(std::string("stats.json unreadable: ") + e.what());
      return out;
    }
    out.sim = stats.value("sim_time", 0.0);
    const json g = world.value("gravity", json::array({0.0, -9.81}));
    const double gravity[2] = {g[0].get<double>(), g[1].get<double>()};
    for (const std::string& f :
         rugosim::testing::check_run(*rows, masses, gravity, scene_height(scene),
                                     rugosim::testing::closed_container(scene), stats)) {
      failures->push_back(f);
    }
  }
  if (trajectories[0] != trajectories[1]) {
    failures->push_back("trajectory differs between --threads 1 and --threads 2");
  }
  check_resume(p, file, fps, dir, trajectories[0], o.guard, failures);
  return out;
}

bool parse_options(int argc, char** argv, Options* o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--program") {
      o->program = value();
    } else if (a == "--seeds") {
      const std::string v = value();
      const auto colon = v.find(':');
      if (colon == std::string::npos) return false;
      o->first = std::stol(v.substr(0, colon));
      o->last = std::stol(v.substr(colon + 1));
    } else if (a == "--minutes") {
      o->minutes = std::stod(value());
    } else if (a == "--first-seed") {
      o->first = std::stol(value());
    } else if (a == "--scenes") {
      o->scenes = value();
    } else if (a == "--work") {
      o->work = value();
    } else if (a == "--keep") {
      o->keep = value();
    } else if (a == "--csv") {
      o->csv = value();
    } else if (a == "--guard") {
      o->guard = std::stoi(value());
    } else {
      return false;
    }
  }
  return !o->program.empty() && (o->last >= o->first || o->minutes > 0.0 || !o->scenes.empty());
}

void summarise(const std::vector<Outcome>& all, int failed) {
  std::map<std::string, int> refusals;
  std::vector<const Outcome*> ran;
  for (const Outcome& o : all) {
    if (o.verdict == "refused") {
      ++refusals[o.reason];
    } else if (o.sim > 0.0) {
      ran.push_back(&o);
    }
  }
  std::size_t refused = 0;
  for (const auto& [reason, count] : refusals)
    refused += static_cast<std::size_t>(count);
  std::printf("\nstress: %zu scenes, %zu run, %d failed, %zu refused by validate\n", all.size(),
              all.size() - refused, failed, refused);
  for (const auto& [reason, count] : refusals)
    std::printf("  refused %d x: %s\n", count, reason.c_str());
  std::sort(ran.begin(), ran.end(),
            [](const Outcome* a, const Outcome* b) { return a->wall / a->sim > b->wall / b->sim; });
  std::printf("slowest (wall s per simulated s):\n");
  for (std::size_t k = 0; k < std::min<std::size_t>(5, ran.size()); ++k) {
    const Outcome& o = *ran[k];
    std::printf("  %8.2f  %s (%s, %s, %zu bodies, scale %.3g m)\n", o.wall / o.sim, o.name.c_str(),
                o.kind.c_str(), o.accuracy.c_str(), o.bodies, o.scale);
  }
  std::printf("cost by scale (median and max wall s per simulated s):\n");
  for (int decade = -3; decade <= 1; ++decade) {
    std::vector<double> cost;
    for (const Outcome* o : ran) {
      if (o->scale > 0.0 && std::floor(std::log10(o->scale)) == decade)
        cost.push_back(o->wall / o->sim);
    }
    if (cost.empty()) continue;
    std::sort(cost.begin(), cost.end());
    std::printf("  1e%+d m: %3zu scenes, median %.3g, max %.3g\n", decade, cost.size(),
                cost[cost.size() / 2], cost.back());
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const char* p = std::getenv("RUGOSIM_PROGRAM")) o.program = p;
  if (!parse_options(argc, argv, &o)) {
    std::fprintf(stderr,
                 "usage: stress_runner --program P (--seeds A:B | --minutes M [--first-seed S] | "
                 "--scenes DIR) [--work DIR] [--keep DIR] [--csv FILE] [--guard SECONDS]\n");
    return 2;
  }
  fs::create_directories(o.work);
  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    csv << "scene,kind,scale,accuracy,bodies,verdict,reason,wall_s,sim_s\n";
  }
  const auto start = std::chrono::steady_clock::now();
  const auto minutes_spent = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.0;
  };
  std::vector<Outcome> all;
  int failed = 0;
  const auto record = [&](Outcome out, const std::vector<std::string>& failures, const json& scene,
                          const std::string& keep_name) {
    if (out.verdict.empty()) out.verdict = failures.empty() ? "ok" : "FAILED";
    std::printf("%-28s %-8s %-8s %3zu bodies  scale %-9.3g %-7s %6.2f s wall  %s\n",
                out.name.c_str(), out.kind.c_str(), out.accuracy.c_str(), out.bodies, out.scale,
                out.verdict.c_str(), out.wall, out.reason.c_str());
    for (const std::string& f : failures)
      std::printf("    %s\n", f.c_str());
    std::fflush(stdout);
    if (!failures.empty()) {
      ++failed;
      if (!o.keep.empty() && !keep_name.empty()) {
        fs::create_directories(o.keep);
        std::ofstream(o.keep / keep_name) << scene.dump(1) << '\n';
      }
    }
    if (csv.is_open()) {
      csv << out.name << ',' << out.kind << ',' << out.scale << ',' << out.accuracy << ','
          << out.bodies << ',' << out.verdict << ",\"" << out.reason << "\"," << out.wall << ','
          << out.sim << '\n';
    }
    all.push_back(std::move(out));
  };

  if (!o.scenes.empty()) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(o.scenes))
      if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
      const json scene = json::parse(read_text(f), nullptr, true, true);
      std::vector<std::string> failures;
      Outcome out = run_scene(o, scene, f.stem().string(), &failures);
      out.kind = "kept";
      record(std::move(out), failures, scene, "");
    }
  } else {
    for (long seed = o.first; o.minutes > 0.0 ? minutes_spent() < o.minutes : seed <= o.last;
         ++seed) {
      const auto s = rugosim::testing::random_stress_scene(static_cast<std::uint64_t>(seed));
      std::vector<std::string> failures;
      Outcome out = run_scene(o, s.scene, "seed_" + std::to_string(seed), &failures);
      out.kind = s.kind;
      out.scale = s.scale;
      record(std::move(out), failures, s.scene, "seed_" + std::to_string(seed) + ".json");
    }
  }
  summarise(all, failed);
  return failed == 0 ? 0 : 1;
}
