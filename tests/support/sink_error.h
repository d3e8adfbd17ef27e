// The message of the SinkError an action throws (frame_sink.h): the sink tests check that
// failures name the file and the reason.
#pragma once

#include <functional>
#include <string>

#include <gtest/gtest.h>

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

}  // namespace rugosim::testing
