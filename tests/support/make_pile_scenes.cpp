// Writes scenes/pile_50.json, pile_200.json and pile_1000.json from the pile of the tests and
// benchmarks (pile_scene_json.h). Usage: make_pile_scenes SOURCE_DIR
#include <cstdio>
#include <fstream>
#include <string>

#include "support/pile_scene_json.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_pile_scenes SOURCE_DIR\n");
    return 2;
  }
  for (const std::size_t n : {50u, 200u, 1000u}) {
    rugosim::testing::PileSpec spec;
    spec.bodies = n;
    const std::string name = "pile_" + std::to_string(n);
    const std::string path = std::string(argv[1]) + "/scenes/" + name + ".json";
    std::ofstream file(path, std::ios::binary);
    file << rugosim::testing::pile_scene_json(spec, name, 5.0);
    if (!file) {
      std::fprintf(stderr, "make_pile_scenes: cannot write %s\n", path.c_str());
      return 1;
    }
    std::printf("wrote %s\n", path.c_str());
  }
  return 0;
}
