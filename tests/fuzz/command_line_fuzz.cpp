// libFuzzer target for the command line, the sibling of scene_loader_fuzz: any bytes, cut at
// NUL bytes into arguments, are parsed as `rugosim ARGS...` with the program's own options
// (render/app/command_line.h), without running the command. A parse either fails with
// CLI11's ParseError (exit 2 in the program) or leaves every number finite and in its range,
// and a run of any preset built from the durations and rates given either has frames the
// counters hold or is refused with a message (run_length.h). Any other exception, a crash, a
// sanitizer report or a broken invariant aborts. tests/fuzz/run_fuzz.sh runs it.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "engine/dynamics/accuracy.h"
#include "render/app/command_line.h"
#include "render/app/run_length.h"

namespace {

[[noreturn]] void fail(const std::string& why) {
  std::fprintf(stderr, "command_line_fuzz: %s\n", why.c_str());
  std::abort();
}

void check_knobs(const rugosim::app::AccuracyOverride& accuracy) {
  if (accuracy.preset && !rugosim::accuracy_preset(*accuracy.preset)) fail("an unknown preset");
  for (const auto& [key, value] : accuracy.knobs) {
    const rugosim::AccuracyKnob* knob = rugosim::find_accuracy_knob(key);
    if (knob == nullptr || !knob->valid(value)) fail("knob " + key + " out of its range");
  }
}

void check_run(const std::optional<double>& duration, const std::optional<double>& fps) {
  if (duration && !(std::isfinite(*duration) && *duration > 0.0)) fail("a bad duration");
  if (fps && !(std::isfinite(*fps) && *fps > 0.0 && *fps <= 1000.0)) fail("a bad fps");
  for (const std::string& name : rugosim::accuracy_preset_names()) {
    const double shortest = rugosim::accuracy_preset(name)->toi_tolerance;
    const double d = duration.value_or(5.0);
    const double f = fps.value_or(30.0);
    const rugosim::app::RunFrames run = rugosim::app::run_frames(d, "d", f, "f", shortest);
    if (run.error.empty()) {
      if (run.last < 1 || static_cast<double>(run.last) + 1.0 > rugosim::app::kMaxRunFrames)
        fail("a run accepted with a frame count out of bounds");
      if (d > shortest * rugosim::app::kMaxStepsOfClock) fail("a run past the clock accepted");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args = {"rugosim"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < 32; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current.push_back(static_cast<char>(data[i]));
    }
  }
  if (!current.empty() && args.size() < 32) args.push_back(current);
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);

  const auto command_line = rugosim::app::make_command_line(2);
  rugosim::app::CommandLine& c = *command_line;
  try {
    c.app.parse(static_cast<int>(args.size()), argv.data());
  } catch (const CLI::ParseError&) {
    return 0;  // the program prints it and exits 2 (or 0 for --help and --version)
  }
  rugosim::app::finish_parse(c);
  if (c.simulate->parsed()) {
    check_knobs(c.sim.accuracy);
    if (c.sim.threads < 1 || c.sim.threads > 256) fail("simulate --threads out of range");
    check_run(c.sim.duration, c.sim.fps);
  }
  if (c.render->parsed()) {
    const rugosim::app::RenderOptions& r = c.render_options;
    check_knobs(r.accuracy);
    if (r.threads < 1 || r.threads > 256) fail("render --threads out of range");
    if (r.crf < 0 || r.crf > 51) fail("render --crf out of range");
    if (r.png_level < 0 || r.png_level > 9) fail("render --png-level out of range");
    if (r.png_workers < 1 || r.png_workers > 64) fail("render --png-workers out of range");
    if (r.gl_threads && (*r.gl_threads < 0 || *r.gl_threads > 64)) fail("bad --gl-threads");
    if (r.strip > 1000) fail("render --strip out of range");
    check_run(r.duration, r.fps);
  }
  if (c.snapshot->parsed()) {
    check_knobs(c.snap.accuracy);
    if (c.snap.threshold < 0 || c.snap.threshold > 255) fail("snapshot --threshold out of range");
    if (!(c.snap.max_share >= 0.0 && c.snap.max_share <= 1.0)) fail("a bad --max-share");
  }
  return 0;
}
