#include "render/app/progress.h"

#include <algorithm>
#include <string>
#include <unistd.h>

#include <fmt/core.h>

namespace rugosim::app {

Progress::Progress(double total, std::FILE* out, Unit unit)
    : total_(total),
      out_(out),
      unit_(unit),
      terminal_(::isatty(::fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

double Progress::wall_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(double simulated) {  // or frames
  const auto now = std::chrono::steady_clock::now();
  const double wall = wall_seconds();
  const double share = total_ > 0.0 ? std::clamp(simulated / total_, 0.0, 1.0) : 1.0;
  const double speed = wall > 0.0 ? simulated / wall : 0.0;  // simulated s per wall s
  const double eta = speed > 0.0 ? (total_ - simulated) / speed : 0.0;
  if (terminal_) {
    // Redraw at most ten times a second.
    if (now - last_print_ < std::chrono::milliseconds(100) && share < 1.0) return;
    last_print_ = now;
    constexpr std::size_t kWidth = 30;
    const auto filled = static_cast<std::size_t>(share * static_cast<double>(kWidth));
    if (unit_ == Unit::kFrames) {
      fmt::print(out_, "\r[{}{}] {:.0f}/{:.0f} frames  {:.3g}/s  ETA {:.0f} s ",
                 std::string(filled, '#'), std::string(kWidth - filled, '-'), simulated, total_,
                 speed, eta);
    } else {
      fmt::print(out_, "\r[{}{}] {:.2f}/{:.2f} s  {:.3g}x  ETA {:.0f} s ", std::string(filled, '#'),
                 std::string(kWidth - filled, '-'), simulated, total_, speed, eta);
    }
    std::fflush(out_);
    return;
  }
  const int tenth = static_cast<int>(share * 10.0);
  if (tenth > last_tenth_ || now - last_print_ > std::chrono::seconds(10)) {
    last_tenth_ = tenth;
    last_print_ = now;
    if (unit_ == Unit::kFrames) {
      fmt::print(out_,
                 "progress: {:.0f}/{:.0f} frames rendered ({:.0f}%), {:.3g} frames/s, ETA {:.0f} "
                 "s\n",
                 simulated, total_, 100.0 * share, speed, eta);
    } else {
      fmt::print(out_,
                 "progress: {:.2f}/{:.2f} s simulated ({:.0f}%), {:.3g}x real time, ETA {:.0f} "
                 "s\n",
                 simulated, total_, 100.0 * share, speed, eta);
    }
    std::fflush(out_);
  }
}

void Progress::finish() {
  if (terminal_) fmt::print(out_, "\n");
}

}  // namespace rugosim::app
