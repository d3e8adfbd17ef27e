// The first exception of several threads working together (the render pipeline's stages, a
// clip sink's writer and encoder): the later ones are consequences of stopping, so only the
// first is kept, to be rethrown on the thread that reports.
#pragma once

#include <exception>
#include <mutex>

namespace rugosim {

class FirstError {
 public:
  // Keeps the exception in flight (call from a catch block) unless one is kept already.
  void capture() {
    const std::lock_guard lock(mutex_);
    if (!error_) error_ = std::current_exception();
  }
  // Rethrows the kept exception; does nothing when there is none.
  void rethrow() {
    const std::lock_guard lock(mutex_);
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr error_;
};

}  // namespace rugosim
