#include "render/app/crossing_report.h"

#include <fmt/core.h>

#include "engine/core/number_text.h"
#include "render/app/scene_input.h"

namespace rugosim::app {

std::string crossing_warning(const World& world) {
  if (!world.first_crossing()) return {};
  const CrossingRecord& c = *world.first_crossing();
  // The depth comes from sampled boundaries (overlap_depth.h): flat faces crossing by a
  // rounding show none.
  const std::string depth =
      c.depth > 0.0 ? number_text(c.depth) + " m deep" : "by less than the sampled boundaries show";
  return fmt::format(
      "warning: t = {} s: bodies \"{}\" and \"{}\" cross, {}: a bounded loop ran out and its "
      "fallback accepted a crossing state (stats.json: crossings, first_crossing; --strict "
      "makes this exit 1)",
      number_text(c.time, 9), world.name(c.body_a), world.name(c.body_b), depth);
}

void CrossingWatch::check(const World& world, std::FILE* out) {
  if (reported_ || !world.first_crossing()) return;
  reported_ = true;
  fmt::print(out, "{}\n", crossing_warning(world));
}

int strict_exit_code(const World& world, bool strict, int code, std::FILE* out) {
  if (!strict || code == kExitInterrupted || world.stats().crossings == 0) return code;
  const CrossingRecord& c = *world.first_crossing();
  fmt::print(out, "error: --strict: {} accepted state{} crossed, the first at t = {} s\n",
             world.stats().crossings, world.stats().crossings == 1 ? "" : "s",
             number_text(c.time, 9));
  return kExitFailure;
}

}  // namespace rugosim::app
