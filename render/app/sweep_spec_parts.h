// Reading the parts of a sweep spec (sweep_spec.h) that stand alone: names, measures and the
// command. Internal to sweep_spec.cpp, which reads the whole spec; errors go to the Reader with
// their JSON path, as the scene loader's do.
#pragma once

#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/scene/json_reader.h"
#include "render/app/sweep_spec.h"

namespace rugosim::app::sweep_spec_parts {

// A name the CSV and the expressions can use, not yet `taken` (which it joins).
void check_name(scene_json::Reader& r, const nlohmann::json& v, const std::string& path,
                std::string& out, std::set<std::string>& taken);

// One measure (its source, column, reduction, window; its body checked against `scene`).
void read_measure(scene_json::Reader& r, const nlohmann::json& m, const std::string& path,
                  const nlohmann::json& scene, SweepMeasure& out, std::set<std::string>& taken);

// The command and its options.
void read_command(scene_json::Reader& r, const nlohmann::json& c, const std::string& path,
                  SweepCommand& out);

}  // namespace rugosim::app::sweep_spec_parts
