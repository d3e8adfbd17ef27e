// The run-length checks (render/app/run_length.h): the frames of a run, and the three ways a
// run is refused: no frame after t = 0, more frames than kMaxRunFrames, a duration the clock
// cannot step through at the shortest step.
#include "render/app/run_length.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

namespace {

using rugosim::app::kMaxRunFrames;
using rugosim::app::kMaxStepsOfClock;
using rugosim::app::run_frames;

TEST(RunLength, CountsFramesUpToTheDuration) {
  EXPECT_EQ(run_frames(5.0, "--duration", 30.0, "--fps", 1e-9).last, 150u);
  // 0.1 × 30 rounds to 2.9999999999999996: still three frames.
  EXPECT_EQ(run_frames(0.1, "--duration", 30.0, "--fps", 1e-9).last, 3u);
  EXPECT_EQ(run_frames(0.05, "--duration", 30.0, "--fps", 1e-9).last, 1u);
  EXPECT_TRUE(run_frames(0.05, "--duration", 30.0, "--fps", 1e-9).error.empty());
}

TEST(RunLength, RefusesARunWithoutAFrameAfterTheStart) {
  const auto r = run_frames(5.0, "world.duration", 1e-300, "--fps", 1e-9);
  EXPECT_EQ(r.error,
            "--fps 1e-300 with world.duration 5 s gives no frame after t = 0: expected "
            "duration × fps of at least 1");
  EXPECT_NE(run_frames(0.01, "--duration", 30.0, "render.fps", 1e-9).error, "");
}

TEST(RunLength, RefusesMoreFramesThanTheBound) {
  // Draft's clock reaches 2.8e7 s; 4e6 s at 30 fps is 1.2e8 frames.
  const auto r = run_frames(4e6, "--duration", 30.0, "render.fps", 1e-7);
  EXPECT_NE(r.error.find("gives 1.2e+08 frames: expected at most 1e+08"), std::string::npos)
      << r.error;
  EXPECT_TRUE(run_frames(kMaxRunFrames / 30.0 - 1.0, "--duration", 30.0, "f", 1e-7).error.empty());
}

TEST(RunLength, RefusesADurationTheClockCannotStepThrough) {
  const double longest = 1e-9 * kMaxStepsOfClock;  // about 2.8e5 s at normal
  EXPECT_TRUE(run_frames(longest, "--duration", 1.0, "--fps", 1e-9).error.empty());
  const auto r = run_frames(std::nextafter(longest, 2 * longest), "--duration", 1.0, "--fps", 1e-9);
  EXPECT_NE(r.error.find("expected at most 281475 s"), std::string::npos) << r.error;
  // At that duration, the clock still tells apart the shortest step to 1/16 of it.
  EXPECT_LE(longest * 0x1p-52, 1e-9 / 16.0);
  EXPECT_NE(run_frames(1e300, "--duration", 30.0, "--fps", 1e-9).error, "");
}

}  // namespace
