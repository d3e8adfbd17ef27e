#include "engine_comparison.h"

#include <algorithm>
#include <fstream>
#include <utility>

#include <fmt/core.h>

namespace rugosim::study {
namespace {

// A run's error on one quantity, or a negative value when it did not compare it.
double part(const EngineRun& run, const std::string& quantity) {
  for (const auto& [name, error] : run.error.parts) {
    if (name == quantity) return error;
  }
  return -1.0;
}

}  // namespace

void append_engine_comparison(const std::filesystem::path& path,
                              const std::vector<EngineRun>& runs) {
  // (scene, quantity) in the order first seen.
  std::vector<std::pair<std::string, std::string>> quantities;
  for (const EngineRun& r : runs) {
    for (const auto& p : r.error.parts) {
      const std::pair<std::string, std::string> key(r.scene, p.first);
      if (std::find(quantities.begin(), quantities.end(), key) == quantities.end())
        quantities.push_back(key);
    }
  }
  std::ofstream out(path, std::ios::app);
  out << "\n## rugosim against Box2D, at equal wall time\n\n"
         "Each engine's settings on the same closed forms: relative error (wall time of the run). "
         "★ marks the Pareto front: no other run, of either engine, is both faster and more "
         "accurate. The last column says which engine is more accurate at equal or lower wall "
         "time: the engine of the most accurate run on the front, from that run's wall time, "
         "and the other engine below it where that one has runs on the front too.\n\n"
         "| scene | quantity |";
  std::vector<std::pair<std::string, std::string>> settings;  // (engine, setting)
  for (const EngineRun& r : runs) {
    const std::pair<std::string, std::string> key(r.engine, r.setting);
    if (std::find(settings.begin(), settings.end(), key) == settings.end()) settings.push_back(key);
  }
  for (const auto& [engine, setting] : settings)
    out << fmt::format(" {} {} |", engine, setting);
  out << " more accurate at ≤ wall time |\n|---|---|";
  for (std::size_t i = 0; i <= settings.size(); ++i)
    out << "---|";
  out << "\n";
  for (const auto& [scene, quantity] : quantities) {
    std::vector<const EngineRun*> compared;
    for (const EngineRun& r : runs) {
      if (r.scene == scene && part(r, quantity) >= 0.0) compared.push_back(&r);
    }
    const auto on_front = [&](const EngineRun* r) {
      return std::none_of(compared.begin(), compared.end(), [&](const EngineRun* o) {
        return o != r && o->wall_s <= r->wall_s && part(*o, quantity) <= part(*r, quantity) &&
               (o->wall_s < r->wall_s || part(*o, quantity) < part(*r, quantity));
      });
    };
    out << fmt::format("| {} | {} |", scene, quantity);
    for (const auto& [engine, setting] : settings) {
      const auto it = std::find_if(compared.begin(), compared.end(), [&](const EngineRun* r) {
        return r->engine == engine && r->setting == setting;
      });
      if (it == compared.end()) {
        out << " — |";
        continue;
      }
      out << fmt::format(" {:.2e} ({:.2g} ms){} |", part(**it, quantity), 1e3 * (*it)->wall_s,
                         on_front(*it) ? " ★" : "");
    }
    const EngineRun* best = nullptr;
    bool rugosim_on_front = false, box2d_on_front = false;
    for (const EngineRun* r : compared) {
      if (!on_front(r)) continue;
      (r->engine == "rugosim" ? rugosim_on_front : box2d_on_front) = true;
      if (best == nullptr || part(*r, quantity) < part(*best, quantity)) best = r;
    }
    if (best == nullptr) {
      out << " — |\n";
      continue;
    }
    // Both on the front: the most accurate run's engine wins where time allows it, the other
    // is the one to use below that run's wall time.
    const std::string other = best->engine == "rugosim" ? "Box2D" : "rugosim";
    out << fmt::format(" {} |\n", rugosim_on_front && box2d_on_front
                                      ? fmt::format("{} from {:.2g} ms; {} below", best->engine,
                                                    1e3 * best->wall_s, other)
                                      : fmt::format("{} at every wall time", best->engine));
  }
}

}  // namespace rugosim::study
