// Progress of a long run on stderr (INTERFACE.md): a live bar on a terminal, plain lines every
// tenth of the run (or every 10 s) otherwise, so logs of CI jobs stay readable.
#pragma once

#include <chrono>
#include <cstdio>

namespace rugosim::app {

class Progress {
 public:
  // `total` is the simulated time to reach (s).
  Progress(double total, std::FILE* out);
  // The run has reached `simulated` (s).
  void update(double simulated);
  // Ends the bar's line.
  void finish();
  double wall_seconds() const;

 private:
  double total_;
  std::FILE* out_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  int last_tenth_ = 0;
};

}  // namespace rugosim::app
