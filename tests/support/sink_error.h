// The message of the SinkError an action throws (frame_sink.h): the sink tests check that
// failures name the file and the reason.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "render/image.h"
#include "render/sinks/frame_sink.h"

namespace rugosim::testing {

// The SinkError's message; fails the test (and returns "") when `action` throws none.
inline std::string sink_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const SinkError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no SinkError thrown";
  return {};
}

// For a disk that fills up in the middle of a clip: writes `frames` frames of seeded noise
// (which no encoder squeezes) of width × height to `sink` and closes it, and returns the
// message of the SinkError that stops it. Then checks that the sink is closed all the same: a
// second close() may say again that the clip is incomplete, a third says nothing.
inline std::string sink_error_writing_noise(FrameSink& sink, int width, int height, int frames) {
  const std::string message = sink_error_of([&] {
    Image noise(width, height);
    std::uint32_t state = 12345;
    for (int k = 0; k < frames; ++k) {
      for (std::uint8_t& byte : noise.rgba) {
        state = state * 1664525U + 1013904223U;
        byte = static_cast<std::uint8_t>(state >> 24);
      }
      sink.write(noise, static_cast<std::size_t>(k));
    }
    sink.close();
  });
  try {
    sink.close();
  } catch (const SinkError&) {
  }
  EXPECT_NO_THROW(sink.close());
  return message;
}

}  // namespace rugosim::testing
