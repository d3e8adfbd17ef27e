// What the accuracy study writes of the convergence with the step (convergence.h): one CSV row
// per scene and step, a Markdown section, and a plot of error against step and against wall
// time, log-log, one line per scene.
#pragma once

#include <filesystem>
#include <vector>

#include "convergence.h"

namespace rugosim::study {

void write_convergence_csv(const std::filesystem::path& path,
                           const std::vector<SceneConvergence>& scenes);

// convergence.md: the errors along the step, the orders, the floors and the wall times.
void write_convergence_markdown(const std::filesystem::path& path,
                                const std::vector<SceneConvergence>& scenes);

void write_convergence_plot(const std::filesystem::path& path,
                            const std::vector<SceneConvergence>& scenes);

}  // namespace rugosim::study
