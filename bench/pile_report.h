// What the accuracy study writes of the piles' statistics (pile_statistics.h): one CSV row per
// ensemble member and a Markdown section with each setting's estimates, their confidence
// intervals and whether each differs from the finest setting's.
#pragma once

#include <filesystem>
#include <vector>

#include "pile_statistics.h"

namespace rugosim::study {

void write_piles_csv(const std::filesystem::path& path, const std::vector<PileEnsemble>& ensembles);

// piles.md. The ensembles of a scene are listed in the order given, the one named "finest" the
// yardstick of the others.
void write_piles_markdown(const std::filesystem::path& path,
                          const std::vector<PileEnsemble>& ensembles);

}  // namespace rugosim::study
