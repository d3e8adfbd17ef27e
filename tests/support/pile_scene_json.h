// The pile scene (pile_scene.h) as a scene file, so that the benchmark's piles can be run from
// the command line: scenes/pile_50.json, pile_200.json and pile_1000.json are written by
// tests/support/make_pile_scenes.cpp, and a test checks that each still is this text and that
// it builds the very bodies of pile_scene().
#pragma once

#include <string>

#include "support/pile_scene.h"

namespace rugosim::testing {

// The scene file (JSON with a header comment) of the pile, `duration` s long, named `name`.
// Numbers are written in their shortest exact form, so the file builds bit-identical bodies.
std::string pile_scene_json(const PileSpec& spec, const std::string& name, double duration);

}  // namespace rugosim::testing
