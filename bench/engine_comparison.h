// rugosim against Box2D on the validation scenes' closed forms (issue 17): each engine's
// settings as points of error against wall time, per compared quantity, and which of them no
// other beats on both (the Pareto front): the engine more accurate at equal or lower wall time.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "accuracy_metrics.h"

namespace rugosim::study {

// One run of a validation scene by one engine at one setting.
struct EngineRun {
  std::string engine;   // "rugosim" or "Box2D"
  std::string setting;  // "draft", "60 Hz 8/3", ...
  std::string scene;
  double wall_s = 0.0;
  ClosedFormError error;
};

// Appends to `path` (Markdown) a table per compared quantity: every run's error and wall time,
// the Pareto front, and the verdict: which engine's runs are on it.
void append_engine_comparison(const std::filesystem::path& path,
                              const std::vector<EngineRun>& runs);

}  // namespace rugosim::study
