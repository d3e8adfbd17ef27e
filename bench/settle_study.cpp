// How a pile settles (docs/research/resting-contact.md §8.9): runs a scene, or the benchmark's
// pile of N bodies with a chosen seed, with sleeping on or off, and every `--window` seconds of
// world time prints one row: the largest net displacement of a movable body over the last
// second, in its narrowest contact band (issue 14's creep measure, taken over every body, not
// only those that fall asleep), how many bodies moved more than their band, the mean vertical
// displacement over that second and the bodies' mean height, and what the contact model did in
// the window (collisions, micro-collisions, fallbacks, steps). A settled pile reads 0 bands and
// no events; a pile that a sleep test freezes while it compacts reads bands > 1 until it sleeps.
//
//   settle_study --pile 200 --seed 3 --sleep off --seconds 6
//   settle_study scenes/pile_50.json --accuracy draft --csv out/settle.csv
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <fmt/ostream.h>

#include "engine/core/thread_pool.h"
#include "engine/dynamics/accuracy.h"
#include "engine/dynamics/world.h"
#include "engine/scene/scene_world.h"
#include "render/app/accuracy_options.h"
#include "render/app/scene_input.h"
#include "support/pile_scene.h"
#include "support/rest_creep.h"

namespace rugosim::study {
namespace {

struct Options {
  std::string scene;  // a scene file, or empty for --pile
  std::size_t pile = 0;
  std::uint64_t seed = 1;
  std::string sleep = "off";
  double seconds = 6.0;
  double window = 0.25;  // s between rows
  double frame = 0.025;  // s between recorded poses
  std::string csv;
  app::AccuracyOverride accuracy;
  int threads = 1;
};

// The World to study: the scene's (accuracy overrides applied) or the pile's, with sleeping as
// asked. Null after printing why.
std::unique_ptr<World> make_world(const Options& o) {
  if (!o.scene.empty()) {
    std::optional<app::LoadedScene> loaded =
        app::load_scene_or_report(o.scene, o.accuracy, o.threads);
    if (!loaded) return nullptr;
    WorldSettings settings = world_settings(loaded->scene);
    settings.threads = o.threads;
    settings.sleep.enabled = o.sleep == "on";
    settings.record_events = false;
    auto world = std::make_unique<World>(settings);
    const std::vector<RigidBodyDesc> descs = body_descriptions(loaded->scene);
    for (std::size_t i = 0; i < descs.size(); ++i)
      world->add_body(RigidBody(descs[i]), loaded->scene.bodies[i].name);
    return world;
  }
  testing::PileSpec spec;
  spec.bodies = o.pile;
  spec.seed = o.seed;
  const std::string preset = o.accuracy.preset.value_or("normal");
  std::optional<Accuracy> accuracy = accuracy_preset(preset);
  if (!accuracy) {
    fmt::print(stderr, "error: no accuracy preset \"{}\"\n", preset);
    return nullptr;
  }
  // Knob options override the preset, as they do a scene's.
  for (const auto& [key, value] : o.accuracy.knobs)
    find_accuracy_knob(key)->set(*accuracy, value);
  WorldSettings settings = with_accuracy(WorldSettings{}, *accuracy);
  settings.threads = o.threads;
  settings.sleep.enabled = o.sleep == "on";
  settings.record_events = false;
  auto world = std::make_unique<World>(settings);
  for (const testing::PileBody& b : testing::pile_scene(spec))
    world->add_body(RigidBody(b.desc), b.name);
  return world;
}

struct Frame {
  std::vector<Vec2> position;
  std::vector<double> narrowest_band;  // m, +inf without contacts
};

Frame record(const World& world) {
  Frame f;
  f.position.resize(world.body_count());
  for (std::size_t i = 0; i < world.body_count(); ++i)
    f.position[i] = world.body(i).state().position;
  f.narrowest_band = testing::narrowest_contact_bands(world);
  return f;
}

int run(const Options& o) {
  std::unique_ptr<World> world = make_world(o);
  if (!world) return app::kExitUsage;
  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv);
    if (!csv) {
      fmt::print(stderr, "error: cannot write {}\n", o.csv);
      return app::kExitFailure;
    }
  }
  const std::string header =
      "time,worst_bands,worst_body,over_band,mean_dy,mean_height,collisions,micro_collisions,"
      "fallbacks,steps,asleep";
  fmt::print("{}\n", header);
  if (csv) fmt::print(csv, "{}\n", header);

  const auto frames_per_second = static_cast<std::size_t>(std::lround(1.0 / o.frame));
  const auto frames_per_window = static_cast<std::size_t>(std::lround(o.window / o.frame));
  const auto frames = static_cast<std::size_t>(std::lround(o.seconds / o.frame));
  std::vector<Frame> history;
  StepStats last = world->stats();
  for (std::size_t k = 1; k <= frames; ++k) {
    world->advance_to(static_cast<double>(k) * o.frame);
    history.push_back(record(*world));
    if (k % frames_per_window != 0 || k <= frames_per_second) continue;
    const Frame& now = history[k - 1];
    const Frame& then = history[k - 1 - frames_per_second];
    double worst = 0.0;
    std::size_t worst_body = 0;
    std::size_t over = 0;
    std::size_t movers = 0;
    std::size_t asleep = 0;
    double dy = 0.0;
    double height = 0.0;
    for (std::size_t i = 0; i < world->body_count(); ++i) {
      if (world->body(i).fixed()) continue;
      ++movers;
      asleep += world->asleep(i) ? 1u : 0u;
      const Vec2 moved = now.position[i] - then.position[i];
      dy += moved.y();
      height += now.position[i].y();
      if (!std::isfinite(now.narrowest_band[i])) continue;  // touches nothing: not resting
      const double bands = moved.norm() / now.narrowest_band[i];
      over += bands > 1.0 ? 1u : 0u;
      if (bands > worst) {
        worst = bands;
        worst_body = i;
      }
    }
    const StepStats& s = world->stats();
    const double n = static_cast<double>(std::max<std::size_t>(movers, 1));
    const std::string row = fmt::format(
        "{:.3f},{:.3f},{},{},{:.6f},{:.6f},{},{},{},{},{}", world->time(), worst,
        world->name(worst_body), over, dy / n, height / n, s.collisions - last.collisions,
        s.contacts - last.contacts, s.fallbacks - last.fallbacks, s.steps - last.steps, asleep);
    fmt::print("{}\n", row);
    if (csv) fmt::print(csv, "{}\n", row);
    last = s;
  }
  return app::kExitOk;
}

}  // namespace
}  // namespace rugosim::study

int main(int argc, char** argv) {
  rugosim::study::Options o;
  o.threads = rugosim::available_cpus();
  CLI::App app{"How a pile settles: creep in contact bands and contact events per window"};
  app.add_option("scene", o.scene, "Scene file (or --pile N)");
  app.add_option("--pile", o.pile, "The benchmark's pile of N bodies instead of a scene file")
      ->check(CLI::Range(1, 5000));
  app.add_option("--seed", o.seed, "Seed of the pile's shapes and places")->capture_default_str();
  app.add_option("--sleep", o.sleep, "Sleeping on or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  app.add_option("--seconds", o.seconds, "World time to run (s)")
      ->check(CLI::Range(1.5, 600.0))
      ->capture_default_str();
  app.add_option("--window", o.window, "World time between rows (s, a multiple of 0.025)")
      ->check(CLI::Range(0.025, 10.0))
      ->capture_default_str();
  app.add_option("--csv", o.csv, "Also write the rows to this CSV file");
  rugosim::app::add_accuracy_options(app, o.accuracy);
  rugosim::app::add_threads_option(app, o.threads);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // As the program does (render/app/main.cpp): --help exits 0, usage errors 2.
    return app.exit(e) == 0 ? rugosim::app::kExitOk : rugosim::app::kExitUsage;
  }
  if (o.scene.empty() == (o.pile == 0)) {
    std::fputs("error: give a scene file or --pile N (one of them)\n", stderr);
    return rugosim::app::kExitUsage;
  }
  return rugosim::study::run(o);
}
