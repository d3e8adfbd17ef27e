// Progress of a long run on stderr (INTERFACE.md): a live bar on a terminal, plain lines every
// tenth of the run (or every 10 s) otherwise, so logs of CI jobs stay readable.
#pragma once

#include <chrono>
#include <cstdio>

namespace rugosim::app {

class Progress {
 public:
  enum class Unit { kSimulatedSeconds, kFrames };
  // `total` is the simulated time to reach (s), or the frames to render.
  Progress(double total, std::FILE* out, Unit unit = Unit::kSimulatedSeconds);
  // The run has reached `done` (s simulated, or frames).
  void update(double done);
  // Ends the bar's line.
  void finish();
  double wall_seconds() const;

 private:
  double total_;
  std::FILE* out_;
  Unit unit_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  int last_tenth_ = 0;
};

}  // namespace rugosim::app
