// How many frames a run has, checked before anything is simulated or written: frames
// k = 0..last at t = k / fps up to the duration. A run must have a frame after t = 0, a frame
// count that memory and counters hold, and a duration whose clock still tells apart the
// shortest step the accuracy allows (toi_tolerance); otherwise the command refuses it with
// exit 2 instead of simulating nothing, overflowing, or stepping forever at a time that
// rounding no longer moves.
#pragma once

#include <cstddef>
#include <string>

namespace rugosim::app {

// The most frames a run may have: 10^8 (over 27 hours at the 1000 fps that render.fps allows).
inline constexpr double kMaxRunFrames = 1e8;

// A duration may be at most this many shortest steps (2^48): at time t a double resolves
// t·2^-52, so the shortest step is still resolved to 1/16 at the end of the run.
inline constexpr double kMaxStepsOfClock = 281474976710656.0;

struct RunFrames {
  std::size_t last = 0;  // the last frame's index (frames 0..last)
  std::string error;     // empty when the run is valid
};

// The frames of a run of `duration` s at `fps`, or why there are none. The sources name where
// each value came from in the message ("--duration", "world.duration"); `shortest_step` is
// the World's min_step (toi_tolerance), s. Both values are finite and positive (the option
// and scene checks ran first).
RunFrames run_frames(double duration, const std::string& duration_source, double fps,
                     const std::string& fps_source, double shortest_step);

}  // namespace rugosim::app
