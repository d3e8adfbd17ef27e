// The validation scenes in Box2D at three settings, and the tables of their closed-form errors.
#include "box2d_validation.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include <fmt/core.h>

#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_world.h"

namespace rugosim::bench {
namespace {

Scene load(const std::string& path) {
  SceneLoad loaded = load_scene_file(path);
  if (!loaded.ok()) throw std::runtime_error(path + ": the scene does not load");
  return std::move(loaded.scene);
}

bool has_disk(const Scene& scene) {
  return std::any_of(scene.bodies.begin(), scene.bodies.end(),
                     [](const BodySpec& b) { return b.shape.kind == ShapeKind::kCircle; });
}

double scale_for(const Scene& scene, const std::string& path) {
  SceneWorld built = build_world(scene, path);
  if (!built.world) throw std::runtime_error(path + ": the scene does not build");
  return suggested_length_scale(*built.world);
}

// Scenes in the order they first appear in the results.
std::vector<std::string> scenes_of(const std::vector<Box2dClosedForm>& results) {
  std::vector<std::string> scenes;
  for (const Box2dClosedForm& r : results) {
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
  }
  return scenes;
}

const Box2dClosedForm* find(const std::vector<Box2dClosedForm>& results, const std::string& scene,
                            const std::string& setting) {
  for (const Box2dClosedForm& r : results) {
    if (r.scene == scene && r.setting == setting) return &r;
  }
  return nullptr;
}

std::string part_error(const Box2dClosedForm* r, const std::string& quantity) {
  if (r == nullptr || !r->error) return "—";
  for (const auto& [name, error] : r->error->parts) {
    if (name == quantity) return fmt::format("{:.3g}", error);
  }
  return "—";
}

}  // namespace

std::vector<Box2dSetting> box2d_validation_settings() {
  Box2dSetting recommended{"box2d 60 Hz", {}};
  Box2dSetting fine{"box2d 240 Hz", {}};
  fine.options.hz = 240.0;
  fine.options.velocity_iterations = 20;
  fine.options.position_iterations = 10;
  Box2dSetting polygon{"box2d 60 Hz 32-gon", {}};
  polygon.options.circles = false;
  return {recommended, fine, polygon};
}

std::vector<Box2dClosedForm> run_box2d_validation(
    const std::vector<std::pair<std::string, std::string>>& name_and_path, int repeats) {
  std::vector<Box2dClosedForm> results;
  for (const auto& [name, path] : name_and_path) {
    const Scene scene = load(path);
    const double scale = scale_for(scene, path);
    for (const Box2dSetting& setting : box2d_validation_settings()) {
      // The 32-gon setting differs from the first only for disks.
      if (!setting.options.circles && !has_disk(scene)) continue;
      Box2dClosedForm result;
      result.scene = name;
      result.setting = setting.label;
      result.options = setting.options;
      result.options.length_scale = scale;
      try {
        const study::Run run = run_box2d_scene(scene, path, result.options, repeats);
        result.wall_s = run.wall_s;
        result.error = study::closed_form_error(name, scene, run);
      } catch (const std::invalid_argument& unsupported) {
        result.unsupported = unsupported.what();
      }
      results.push_back(std::move(result));
    }
  }
  return results;
}

void write_box2d_csv(const std::filesystem::path& path,
                     const std::vector<Box2dClosedForm>& results) {
  std::ofstream out(path);
  out << "scene,setting,hz,velocity_iterations,position_iterations,circles,length_scale,wall_s,"
         "quantity,relative_error\n";
  for (const Box2dClosedForm& r : results) {
    const std::string common =
        fmt::format("{},{},{:g},{},{},{},{:.6g},{:.6g}", r.scene, r.setting, r.options.hz,
                    r.options.velocity_iterations, r.options.position_iterations,
                    r.options.circles ? 1 : 0, r.options.length_scale, r.wall_s);
    if (!r.error) {
      out << fmt::format("{},\"{}\",\n", common,
                         r.unsupported.empty() ? "no closed form" : r.unsupported);
      continue;
    }
    for (const auto& [quantity, error] : r.error->parts)
      out << fmt::format("{},{},{:.6g}\n", common, quantity, error);
  }
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", path.string()));
}

void write_box2d_markdown(const std::filesystem::path& path,
                          const std::vector<Box2dClosedForm>& results) {
  std::vector<std::string> settings;
  for (const Box2dSetting& s : box2d_validation_settings())
    settings.push_back(s.label);
  std::ofstream out(path);
  out << "## Box2D 2.4.1 on the validation scenes\n\n"
         "Relative errors against each scene's closed form (the same functions as rugosim's, "
         "bench/accuracy_metrics.cpp), and Box2D's wall time per run (best of the repeats).\n\n"
         "| scene | quantity |";
  for (const std::string& s : settings)
    out << fmt::format(" {} |", s);
  for (const std::string& s : settings)
    out << fmt::format(" wall ms {} |", s.substr(std::string("box2d ").size()));
  out << "\n|---|---|";
  for (std::size_t k = 0; k < 2 * settings.size(); ++k)
    out << "---:|";
  out << "\n";
  std::vector<std::string> notes;
  for (const std::string& scene : scenes_of(results)) {
    // The quantities of the scene, from its first setting with a closed form.
    std::vector<std::string> quantities;
    for (const Box2dClosedForm& r : results) {
      if (r.scene == scene && !r.unsupported.empty()) {
        notes.push_back(fmt::format("- {} ({}): not run, {}", scene, r.setting, r.unsupported));
      }
      if (r.scene != scene || !r.error || !quantities.empty()) continue;
      for (const auto& part : r.error->parts)
        quantities.push_back(part.first);
    }
    for (const std::string& quantity : quantities) {
      out << fmt::format("| {} | {} |", scene, quantity);
      for (const std::string& s : settings)
        out << fmt::format(" {} |", part_error(find(results, scene, s), quantity));
      for (const std::string& s : settings) {
        const Box2dClosedForm* r = find(results, scene, s);
        out << (r != nullptr && r->error ? fmt::format(" {:.3g} |", 1e3 * r->wall_s) : " — |");
      }
      out << "\n";
    }
  }
  const Box2dSceneOptions defaults;
  out << "\n— : not run (the 32-gon setting only for scenes with a disk).\n";
  for (const std::string& note : notes)
    out << note << "\n";
  out << "\nBox2D units per metre (length_scale):";
  for (const std::string& scene : scenes_of(results)) {
    const Box2dClosedForm* r = find(results, scene, settings.front());
    if (r != nullptr) out << fmt::format(" {} {:.3g};", scene, r->options.length_scale);
  }
  out << " Box2D polygons carry a skin of b2_polygonRadius = 2·b2_linearSlop (1 cm in Box2D "
         "units, so 1 cm / length_scale): a disk rests and bounces that far above a box, which "
         "the bounce ratios, measured from the floor's top, feel more at each lower apex.\n";
  out << fmt::format(
      "\nEach Box2D world is built from the scene file, through the rugosim World built from it "
      "(bench/box2d_scene.h): disks as b2CircleShape (or an inscribed 32-gon, "
      "(32/2π)·sin(2π/32) = 99.36% of the disk's area), boxes as b2PolygonShape boxes, the same "
      "density, placements, velocities and gravity; lengths scaled so that the moving body is "
      "about one Box2D unit across (Box2D's tolerances are absolute). Box2D is single "
      "precision (float). Box2D steps at a fixed 1/hz and a frame takes the state after the last "
      "step not beyond its time. μ of a fixture is the rugosim body's μ = k·max(0, λ − λ_min) on "
      "the boundary it stands for; Box2D would mix sqrt(μa·μb), so a contact listener sets "
      "max(μa, μb) in PreSolve, rugosim's rule. Restitution is the material's ε, mixed by "
      "Box2D's own max(εa, εb), which is rugosim's. Box2D 2.4.1 does not bounce impacts "
      "slower than b2FixtureDef::restitutionThreshold, 1 m/s by default, which would end the "
      "bouncing disk after its second bounce (the third impact comes at 0.96 m/s); it is set to "
      "{:g} m/s here. Gravity is the scene's vector: the incline scenes keep the floor "
      "horizontal and tilt gravity by θ, and Box2D gets the same tilted gravity.\n\n"
      "What Box2D cannot express: friction varying continuously along one boundary (μ is per "
      "fixture: the rough patch floor is one box per run of equal μ along its top face, side by "
      "side, so the blend of λ(t) between segments becomes a step at their joint); the tolerance "
      "bands, micro-collisions "
      "and ε_max of the rugosity model; surfaces that are not convex polygons or circles.\n",
      defaults.restitution_threshold);
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", path.string()));
}

}  // namespace rugosim::bench
