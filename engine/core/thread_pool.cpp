#include "engine/core/thread_pool.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sched.h>
#include <string>

namespace rugosim {
namespace {

// How long a worker waiting for the next loop spins before it blocks: twice the usual gap
// between loops (the World asks for one per step, a fraction of a millisecond apart, and waking
// a blocked thread costs tens of microseconds), within these bounds, so that a pool whose loops
// are rare does not hold a core that other threads (the renderer's, the encoder's) could use.
constexpr std::int64_t kMinSpinNs = 50'000;
constexpr std::int64_t kMaxSpinNs = 2'000'000;
// The caller waits for the workers to leave a loop this long before it blocks.
constexpr auto kJoinSpin = std::chrono::microseconds(100);

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

void relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

}  // namespace

ThreadPool::ThreadPool(int threads) {
  const int workers = std::max(threads, 1) - 1;
  shares_ = std::make_unique<Share[]>(static_cast<std::size_t>(workers) + 1);
  workers_.reserve(static_cast<std::size_t>(workers));
  try {
    for (int i = 0; i < workers; ++i)
      workers_.emplace_back([this, i] { worker_main(i + 1); });
  } catch (...) {
    // Out of threads (a process limit): stop those started, so that none is left unjoined.
    stop_workers();
    throw;
  }
}

void ThreadPool::stop_workers() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  for (std::thread& t : workers_)
    t.join();
  workers_.clear();
}

ThreadPool::~ThreadPool() {
  stop_workers();
}

namespace {

// A share's chunks [front, back) in one word, so that its owner (from the front) and thieves
// (from the back) agree by one compare-and-swap.
constexpr std::uint64_t pack(std::uint64_t front, std::uint64_t back) {
  return front << 32 | back;
}
constexpr std::uint64_t front_of(std::uint64_t range) {
  return range >> 32;
}
constexpr std::uint64_t back_of(std::uint64_t range) {
  return range & 0xffffffffu;
}

}  // namespace

bool ThreadPool::take_chunk(int owner, bool from_front, std::size_t& chunk) {
  std::atomic<std::uint64_t>& range = shares_[static_cast<std::size_t>(owner)].range;
  std::uint64_t r = range.load(std::memory_order_relaxed);
  for (;;) {
    const std::uint64_t front = front_of(r), back = back_of(r);
    if (front >= back) return false;
    const std::uint64_t taken = from_front ? pack(front + 1, back) : pack(front, back - 1);
    if (range.compare_exchange_weak(r, taken, std::memory_order_relaxed)) {
      chunk = static_cast<std::size_t>(from_front ? front : back - 1);
      return true;
    }
  }
}

void ThreadPool::run_chunks(int thread) {
  const auto run = [&](std::size_t chunk) {
    const std::size_t begin = chunk * grain_;
    const std::size_t end = std::min(count_, begin + grain_);
    try {
      (*body_)(begin, end, thread);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
  };
  std::size_t chunk = 0;
  while (take_chunk(thread, true, chunk))
    run(chunk);
  // Then help the others, from the far end of their shares.
  for (int k = 1; k < size(); ++k) {
    const int other = (thread + k) % size();
    while (take_chunk(other, false, chunk))
      run(chunk);
  }
}

void ThreadPool::worker_main(int thread) {
  std::uint64_t seen = 0;
  for (;;) {
    // Wait for a generation newer than the last one served: spin first, then block.
    std::uint64_t now = generation_.load(std::memory_order_acquire);
    const std::int64_t spin_ns = std::clamp<std::int64_t>(
        2 * gap_ns_.load(std::memory_order_relaxed), kMinSpinNs, kMaxSpinNs);
    const auto until = std::chrono::steady_clock::now() + std::chrono::nanoseconds(spin_ns);
    for (int spin = 1; now == seen; ++spin) {
      relax();
      now = generation_.load(std::memory_order_acquire);
      if (spin % 64 == 0 && std::chrono::steady_clock::now() > until) break;
    }
    if (now == seen) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return generation_.load(std::memory_order_acquire) != seen; });
      now = generation_.load(std::memory_order_acquire);
    }
    seen = now;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (stopping_) return;
    }
    run_chunks(thread);
    if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      const std::lock_guard<std::mutex> lock(mutex_);
      done_.notify_one();
    }
  }
}

void ThreadPool::parallel_for(std::size_t count, std::size_t grain, const Body& body) {
  if (count == 0) return;
  // At least one index a chunk, and chunks few enough to number in 32 bits (see pack).
  grain = std::max<std::size_t>({grain, 1, count >> 31});
  if (workers_.empty() || count <= grain) {
    for (std::size_t begin = 0; begin < count; begin += grain)
      body(begin, std::min(count, begin + grain), 0);
    return;
  }
  // The gap since the last loop ended, smoothed (an eighth of each new one).
  const std::int64_t start = now_ns();
  if (last_end_ns_ > 0) {
    const std::int64_t gap = start - last_end_ns_;
    const std::int64_t old = gap_ns_.load(std::memory_order_relaxed);
    gap_ns_.store(old + (gap - old) / 8, std::memory_order_relaxed);
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    body_ = &body;
    count_ = count;
    grain_ = grain;
    error_ = nullptr;
    // Each thread's share of the chunks: the same stretch of indices at every loop, so that
    // the data of a body pair stays in the caches of the core that worked on it last time.
    const std::uint64_t chunks = count / grain + (count % grain != 0 ? 1 : 0);
    const auto threads = static_cast<std::uint64_t>(size());
    for (std::uint64_t t = 0; t < threads; ++t)
      shares_[t].range.store(pack(t * chunks / threads, (t + 1) * chunks / threads),
                             std::memory_order_relaxed);
    busy_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  run_chunks(0);
  // Every worker leaves run_chunks only after the last chunk was taken; wait until all have.
  const auto until = std::chrono::steady_clock::now() + kJoinSpin;
  for (int spin = 1; busy_.load(std::memory_order_acquire) != 0; ++spin) {
    relax();
    if (spin % 64 == 0 && std::chrono::steady_clock::now() > until) break;
  }
  std::exception_ptr error;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return busy_.load(std::memory_order_acquire) == 0; });
    error = error_;
    body_ = nullptr;
  }
  last_end_ns_ = now_ns();
  if (error) std::rethrow_exception(error);
}

int available_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  int cpus = 0;
  if (sched_getaffinity(0, sizeof(set), &set) == 0) cpus = CPU_COUNT(&set);
  if (cpus <= 0) cpus = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // cgroup v2: "max 100000" (no quota) or "<quota> <period>" in microseconds.
  std::ifstream cpu_max("/sys/fs/cgroup/cpu.max");
  std::string quota;
  double period = 0.0;
  if (cpu_max >> quota >> period && quota != "max" && period > 0.0) {
    try {
      const double share = std::stod(quota) / period;
      if (share > 0.0) cpus = std::min(cpus, std::max(1, static_cast<int>(std::ceil(share))));
    } catch (const std::exception&) {
      // An unreadable quota limits nothing.
    }
  }
  return std::max(cpus, 1);
}

}  // namespace rugosim
