// `rugosim snapshot`: visual regression for users' CI. Goldens live in one folder per suite:
// for a scene file `name.json`, `name_<frame>.png` for each frame and `name.json` with what they
// were made with (frames, size, anti-aliasing, backend, renderer string, rugosim version). A
// failing comparison leaves `name_<frame>.actual.png`, `name_<frame>.diff.png` and
// `name.summary.txt` beside them; a passing one removes any left from before.
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "engine/core/version.h"
#include "render/app/clip_render.h"
#include "render/app/commands.h"
#include "render/app/crossing_report.h"
#include "render/app/render_scene.h"
#include "render/app/run_length.h"
#include "render/app/scene_input.h"
#include "render/app/sigint_guard.h"
#include "render/sinks/film_strip.h"
#include "render/sinks/png_io.h"
#include "render/snapshot/image_compare.h"

namespace rugosim::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::size_t kDefaultFrames = 4;

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Goldens are kept small: the best compression, adaptive filters.
const PngSettings kGoldenPng{9, PngFilter::kAll, false, false};

std::size_t parse_number(std::string_view text, std::string_view what) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    throw UsageError(fmt::format("{}: expected a frame number, got \"{}\"", what, text));
  }
  return value;
}

// "0,30,60", "0:90:30" (first:last:step) or "0:3" (step 1), mixed; sorted, no repeats.
std::vector<std::size_t> parse_frame_list(const std::string& text, std::size_t last) {
  std::vector<std::size_t> frames;
  std::stringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    std::vector<std::size_t> parts;
    std::stringstream pieces(item);
    std::string piece;
    while (std::getline(pieces, piece, ':'))
      parts.push_back(parse_number(piece, "--frames"));
    if (parts.empty() || parts.size() > 3) {
      throw UsageError("--frames: expected numbers and ranges A:B or A:B:STEP, got \"" + item +
                       "\"");
    }
    const std::size_t first = parts[0];
    const std::size_t end = parts.size() > 1 ? parts[1] : first;
    const std::size_t step = parts.size() > 2 ? parts[2] : 1;
    if (step == 0 || end < first) throw UsageError("--frames: bad range \"" + item + "\"");
    // Checked before expanding, so that a huge range costs nothing.
    if (end > last) {
      throw UsageError(
          fmt::format("--frames: frame {} is past the clip's last frame, {}", end, last));
    }
    for (std::size_t k = first; k <= end; k += step)
      frames.push_back(k);
  }
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  if (frames.empty()) throw UsageError("--frames: no frame given");
  return frames;
}

struct Suite {
  fs::path dir;      // the goldens
  fs::path output;   // what a failure leaves (the goldens' folder unless --output)
  std::string stem;  // the scene file's name without .json
  fs::path golden(std::size_t frame) const { return dir / fmt::format("{}_{}.png", stem, frame); }
  fs::path actual(std::size_t frame) const {
    return output / fmt::format("{}_{}.actual.png", stem, frame);
  }
  fs::path diff(std::size_t frame) const {
    return output / fmt::format("{}_{}.diff.png", stem, frame);
  }
  fs::path metadata() const { return dir / (stem + ".json"); }
  fs::path summary() const { return output / (stem + ".summary.txt"); }
};

// What the goldens were made with, if they say: frames (within the clip, increasing), size
// (1..16384 a side) and renderer, each optional and checked.
struct Metadata {
  std::optional<std::vector<std::size_t>> frames;
  std::optional<std::pair<int, int>> size;
  std::string renderer;
};

std::optional<Metadata> read_metadata(const Suite& suite, std::size_t last) {
  std::ifstream in(suite.metadata());
  if (!in) return std::nullopt;
  const std::string file = suite.metadata().string();
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {
    throw UsageError(fmt::format("{}: not valid JSON ({})", file, e.what()));
  }
  auto bad = [&](const std::string& key, const std::string& expected) {
    return UsageError(fmt::format("{}: /{}: expected {}; recreate the goldens with --update", file,
                                  key, expected));
  };
  if (!j.is_object()) throw bad("", "an object");
  Metadata m;
  if (j.contains("frames")) {
    const json& frames = j["frames"];
    if (!frames.is_array() || frames.empty()) throw bad("frames", "a list of frame numbers");
    std::vector<std::size_t> list;
    for (const json& f : frames) {
      if (!f.is_number_unsigned() || f.get<std::size_t>() > last ||
          (!list.empty() && f.get<std::size_t>() <= list.back())) {
        throw bad("frames", fmt::format("increasing frame numbers of the clip (0 to {}), got {}",
                                        last, frames.dump()));
      }
      list.push_back(f.get<std::size_t>());
    }
    m.frames = std::move(list);
  }
  if (j.contains("size")) {
    const json& size = j["size"];
    auto side = [](const json& v) { return v.is_number_unsigned() && v >= 1 && v <= 16384; };
    if (!size.is_array() || size.size() != 2 || !side(size[0]) || !side(size[1])) {
      throw bad("size", "[width, height] in pixels, got " + size.dump());
    }
    m.size = std::pair<int, int>(size[0].get<int>(), size[1].get<int>());
  }
  if (j.contains("renderer")) {
    if (!j["renderer"].is_string()) throw bad("renderer", "a string");
    m.renderer = j["renderer"].get<std::string>();
  }
  return m;
}

void write_text(const fs::path& path, const std::string& text) {
  const fs::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.flush()) throw std::runtime_error(path.string() + ": cannot write");
  }
  fs::rename(temporary, path);
}

struct FrameOutcome {
  std::size_t frame = 0;
  std::string status;  // "identical", "passed", "failed", "missing", "written"
  CompareResult result;
};

struct Setup {
  Suite suite;
  ClipPlan plan;
  CompareRule rule;
  std::optional<Metadata> metadata;  // of the goldens there already (also when updating)
  PngSettings png = kGoldenPng;      // of goldens and actual frames: RGBA when transparent
};

Setup make_setup(const SnapshotOptions& o, const LoadedScene& loaded) {
  Setup s;
  s.suite =
      Suite{fs::path(o.golden_dir), fs::path(o.output_dir.empty() ? o.golden_dir : o.output_dir),
            fs::path(o.scene_path).stem().string()};
  if (!o.update && !fs::is_directory(s.suite.dir)) {
    throw UsageError(fmt::format(
        "--golden {}: no such folder; create the goldens with: rugosim snapshot {} --golden {} "
        "--update",
        o.golden_dir, o.scene_path, o.golden_dir));
  }
  const Scene& scene = loaded.scene;
  s.png.keep_alpha = has_transparent_background(scene);
  s.plan.fps = scene.render.fps;
  const RunFrames run = run_frames(scene.duration, "world.duration", s.plan.fps, "render.fps",
                                   loaded.world->settings().min_step);
  if (!run.error.empty()) throw UsageError(run.error);
  const std::size_t last = run.last;
  // An update keeps the suite's frames and size unless told otherwise.
  s.metadata = read_metadata(s.suite, last);
  if (!o.frames.empty()) {
    s.plan.frames = parse_frame_list(o.frames, last);
  } else if (s.metadata && s.metadata->frames) {
    s.plan.frames = *s.metadata->frames;
  } else {
    s.plan.frames = strip_frame_indices(0, last, kDefaultFrames);
  }
  s.plan.width = scene.render.width;
  s.plan.height = scene.render.height;
  if (!o.size.empty()) {
    const std::size_t x = o.size.find('x');
    if (x == std::string::npos) throw UsageError("--size: expected WxH, got \"" + o.size + "\"");
    s.plan.width = static_cast<int>(parse_number(o.size.substr(0, x), "--size W"));
    s.plan.height = static_cast<int>(parse_number(o.size.substr(x + 1), "--size H"));
  } else if (s.metadata && s.metadata->size) {
    std::tie(s.plan.width, s.plan.height) = *s.metadata->size;
  }
  if (s.plan.width < 1 || s.plan.height < 1 || s.plan.width > 16384 || s.plan.height > 16384) {
    throw UsageError(fmt::format("frame size {}x{}: expected 1..16384 pixels a side", s.plan.width,
                                 s.plan.height));
  }
  const std::optional<GlBackend> backend = parse_gl_backend(o.backend);
  if (!backend) throw UsageError("--backend: expected osmesa or egl, got \"" + o.backend + "\"");
  s.plan.backend = *backend;
  const std::optional<AntiAliasing> aa = parse_anti_aliasing(o.anti_aliasing);
  if (!aa) throw UsageError("--aa: expected shader, msaa or none, got \"" + o.anti_aliasing + "\"");
  s.plan.anti_aliasing = *aa;
  std::string unknown;
  s.plan.overlays = parse_overlays(scene.render.overlays, &unknown).value_or(Overlays{});
  s.rule = CompareRule{o.exact, o.threshold, o.max_share};
  if (o.threshold < 0 || o.threshold > 255) throw UsageError("--threshold: expected 0..255");
  if (!(o.max_share >= 0.0 && o.max_share <= 1.0)) throw UsageError("--max-share: expected 0..1");
  return s;
}

json outcome_json(const Suite& suite, const FrameOutcome& f) {
  json j{{"frame", f.frame}, {"status", f.status}, {"golden", suite.golden(f.frame).string()}};
  if (f.status != "missing") {
    const CompareResult& r = f.result;
    j["differing_pixels"] = r.differing_pixels;
    j["failing_pixels"] = r.failing_pixels;
    j["failing_share"] = r.failing_share;
    j["worst"] = r.worst;
    if (r.worst_x >= 0) j["worst_at"] = {r.worst_x, r.worst_y};
    if (r.box_x0 >= 0) j["box"] = {r.box_x0, r.box_y0, r.box_x1, r.box_y1};
    if (r.size_mismatch) {
      j["size_mismatch"] = {{"golden", {r.golden_width, r.golden_height}},
                            {"actual", {r.actual_width, r.actual_height}}};
    }
  }
  if (f.status == "failed" || f.status == "missing") {
    j["actual"] = suite.actual(f.frame).string();
    if (f.status == "failed") j["diff"] = suite.diff(f.frame).string();
  }
  return j;
}

// --update: the frames become the goldens, with what made them.
void write_goldens(const Setup& s, const std::vector<Image>& frames, const std::string& renderer) {
  const Suite& suite = s.suite;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    write_png_file(suite.golden(s.plan.frames[i]).string(), frames[i], s.png);
    fs::remove(suite.actual(s.plan.frames[i]));
    fs::remove(suite.diff(s.plan.frames[i]));
  }
  fs::remove(suite.summary());
  const json metadata{{"scene", suite.stem},
                      {"frames", s.plan.frames},
                      {"size", {s.plan.width, s.plan.height}},
                      {"anti_aliasing", std::string(anti_aliasing_name(s.plan.anti_aliasing))},
                      {"renderer", renderer},
                      {"rugosim", kVersion}};
  write_text(suite.metadata(), metadata.dump(2) + "\n");
  fmt::print(stderr, "wrote {} golden frame{} of {} into {} ({})\n", frames.size(),
             frames.size() == 1 ? "" : "s", suite.stem, suite.dir.string(), renderer);
}

// An unreadable golden: exit 2, after saying how to recreate it.
class BadGolden : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The golden of `frame`, or nullopt when there is none. An unreadable one is an error before
// anything is written.
std::optional<Image> read_golden(const SnapshotOptions& o, const Suite& suite, std::size_t frame) {
  const fs::path golden = suite.golden(frame);
  if (!fs::exists(golden)) return std::nullopt;
  try {
    return read_png_file(golden.string());
  } catch (const PngReadError& e) {
    throw BadGolden(fmt::format(
        "golden {} cannot be read: {}\n(recreate it with: rugosim snapshot {} --golden {} "
        "--update)",
        golden.string(), e.what(), o.scene_path, o.golden_dir));
  }
}

// One frame against its golden; a failure writes the actual and diff images. Appends the
// frame's line to `report`.
FrameOutcome compare_frame(const SnapshotOptions& o, const Setup& s, std::size_t frame,
                           const Image& image, const std::optional<Image>& expected,
                           std::string& report) {
  const Suite& suite = s.suite;
  FrameOutcome f;
  f.frame = frame;
  if (!expected) {
    f.status = "missing";
    write_png_file(suite.actual(frame).string(), image, s.png);
    report += fmt::format(
        "frame {}: no golden {}; create it with: rugosim snapshot {} --golden {} --update\n", frame,
        suite.golden(frame).string(), o.scene_path, o.golden_dir);
    return f;
  }
  f.result = compare_images(*expected, image, s.rule);
  f.status = f.result.identical ? "identical" : f.result.passed ? "passed" : "failed";
  if (!f.result.passed) {
    write_png_file(suite.actual(frame).string(), image, s.png);
    write_png_file(suite.diff(frame).string(), difference_image(*expected, image, s.rule),
                   kGoldenPng);
  }
  report += fmt::format("frame {}: {}: {}\n", frame, f.status, describe(f.result, s.rule));
  return f;
}

void print_json(const Setup& s, bool passed, const std::string& golden_renderer,
                const std::string& renderer, const std::vector<FrameOutcome>& outcomes) {
  json out{
      {"scene", s.suite.stem},
      {"passed", passed},
      {"rule",
       {{"exact", s.rule.exact}, {"threshold", s.rule.threshold}, {"max_share", s.rule.max_share}}},
      {"renderer", {{"golden", golden_renderer}, {"current", renderer}}},
      {"frames", json::array()}};
  for (const FrameOutcome& f : outcomes)
    out["frames"].push_back(outcome_json(s.suite, f));
  fmt::print("{}\n", out.dump(2));
}

// Every frame against its golden: the report on stderr (and in the summary file on failure),
// JSON on stdout when asked. True when all pass.
bool compare_all(const SnapshotOptions& o, const Setup& s, const std::vector<Image>& frames,
                 const std::string& renderer) {
  const Suite& suite = s.suite;
  std::vector<FrameOutcome> outcomes;
  std::string report;
  bool passed = true;
  std::vector<std::optional<Image>> goldens;
  for (const std::size_t frame : s.plan.frames)
    goldens.push_back(read_golden(o, suite, frame));
  for (std::size_t i = 0; i < frames.size(); ++i) {
    outcomes.push_back(compare_frame(o, s, s.plan.frames[i], frames[i], goldens[i], report));
    const std::string& status = outcomes.back().status;
    passed = passed && (status == "identical" || status == "passed");
  }
  const std::string golden_renderer = s.metadata ? s.metadata->renderer : std::string();
  if (!golden_renderer.empty() && golden_renderer != renderer) {
    report += fmt::format("note: the goldens were made with \"{}\"; this renderer is \"{}\"{}\n",
                          golden_renderer, renderer,
                          passed ? "" : ": differences may come from the renderer, not the scene");
  }
  if (passed) {
    for (const FrameOutcome& f : outcomes) {
      fs::remove(suite.actual(f.frame));
      fs::remove(suite.diff(f.frame));
    }
    fs::remove(suite.summary());
  } else {
    write_text(suite.summary(), report);
  }
  fmt::print(stderr, "{}{}: {} ({} frame{})\n", report, suite.stem, passed ? "passed" : "FAILED",
             outcomes.size(), outcomes.size() == 1 ? "" : "s");
  if (!passed) {
    fmt::print(stderr, "actual and diff images and {} are in {}\n",
               suite.summary().filename().string(), suite.output.string());
  }
  if (o.json) print_json(s, passed, golden_renderer, renderer, outcomes);
  return passed;
}

}  // namespace

int run_snapshot(const SnapshotOptions& o) {
  std::optional<LoadedScene> loaded = load_scene_or_report(o.scene_path, o.accuracy, o.threads);
  if (!loaded) return kExitUsage;
  Setup s;
  try {
    s = make_setup(o, *loaded);
    if (o.update) fs::create_directories(s.suite.dir);
    fs::create_directories(s.suite.output);
  } catch (const UsageError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {  // e.g. a folder that cannot be created
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
  choose_rasteriser_threads(std::nullopt);
  const SigintGuard sigint;
  try {
    std::vector<Image> frames;
    std::string renderer;
    const PipelineResult rendered = render_clip(
        *loaded, s.plan, [&](const Image& image, std::size_t) { frames.push_back(image); },
        &SigintGuard::interrupted(), &renderer);
    if (rendered.interrupted) {
      fmt::print(stderr, "interrupted: nothing compared or written\n");
      return kExitInterrupted;
    }
    // The simulation ran on the pipeline's thread: its first crossing is told here, after it.
    CrossingWatch().check(*loaded->world, stderr);
    if (o.update) {
      write_goldens(s, frames, renderer);
      return strict_exit_code(*loaded->world, o.strict, kExitOk, stderr);
    }
    const bool passed = compare_all(o, s, frames, renderer);
    return strict_exit_code(*loaded->world, o.strict, passed ? kExitOk : kExitFailure, stderr);
  } catch (const BadGolden& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kExitFailure;
  }
}

}  // namespace rugosim::app
