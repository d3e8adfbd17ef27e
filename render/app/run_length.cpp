#include "render/app/run_length.h"

#include <cmath>

#include <fmt/core.h>

#include "engine/core/number_text.h"

namespace rugosim::app {

RunFrames run_frames(double duration, const std::string& duration_source, double fps,
                     const std::string& fps_source, double shortest_step) {
  RunFrames r;
  const double longest = shortest_step * kMaxStepsOfClock;
  if (!(duration <= longest)) {
    r.error = fmt::format(
        "{} {} s: expected at most {} s, the longest run whose clock still resolves the "
        "shortest step ({} s, toi_tolerance)",
        duration_source, number_text(duration), number_text(longest), number_text(shortest_step));
    return r;
  }
  // A rounding below a whole frame still counts it (0.1 × 30 is 2.9999999999999996).
  const double frames = std::floor(duration * fps + 1e-9);
  if (!(frames >= 1.0)) {
    r.error = fmt::format(
        "{} {} with {} {} s gives no frame after t = 0: expected duration × fps of at least 1",
        fps_source, number_text(fps), duration_source, number_text(duration));
    return r;
  }
  if (!(frames + 1.0 <= kMaxRunFrames)) {
    r.error = fmt::format("{} {} s at {} {} gives {} frames: expected at most {}", duration_source,
                          number_text(duration), fps_source, number_text(fps),
                          number_text(frames + 1.0), number_text(kMaxRunFrames));
    return r;
  }
  r.last = static_cast<std::size_t>(frames);
  return r;
}

}  // namespace rugosim::app
