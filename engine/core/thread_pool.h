// A fixed set of worker threads for the engine's data-parallel loops (the narrow phase over the
// body pairs of a step), built so that results never depend on the number of threads: every
// index of a loop writes only its own slot, and the caller reads the slots in index order. How
// the indices are shared out changes only who computes a slot, never what is in it: each thread
// owns a contiguous share of the chunks, the same at every loop of the same size, and works
// through it from the front; a thread done with its own share takes chunks from the back of the
// others'. So a body pair is mostly worked on by the same core step after step, its caches
// warm there (with chunks handed to whichever thread was free, each thread ran about a fifth
// slower than alone), and no thread idles while another has work left.
//
// Workers spin for a while after a loop before they block (twice the usual gap between loops,
// within bounds), since the World asks for a loop every step, a fraction of a millisecond apart,
// and waking a blocked thread costs tens of microseconds; a caller that runs alone never waits
// on them (a pool of one thread runs the loop inline).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace rugosim {

class ThreadPool {
 public:
  // `threads` threads in all, the caller's included (so threads − 1 workers); at least 1.
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls body(begin, end, thread) on chunks of at most `grain` indices (more only for a count
  // of 2^31 grains or more, so that chunks number in 32 bits) covering [0, count) once each, on the
  // caller and the workers (thread in [0, size()), 0 for the caller), and returns when all are
  // done. An exception thrown by body is rethrown here (the first one; with workers the other
  // chunks still run, alone the caller stops at it). Not reentrant: one loop at a time per pool.
  using Body = std::function<void(std::size_t begin, std::size_t end, int thread)>;
  void parallel_for(std::size_t count, std::size_t grain, const Body& body);

 private:
  void worker_main(int thread);
  // Tells every worker to leave and joins them.
  void stop_workers();
  // Takes chunks of the current loop until none are left.
  void run_chunks(int thread);
  // Takes one chunk of `owner`'s share, from its front (the owner) or back (another thread).
  bool take_chunk(int owner, bool from_front, std::size_t& chunk);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;              // workers wait here for a new loop
  std::condition_variable done_;              // the caller waits here for the workers
  std::atomic<std::uint64_t> generation_{0};  // a new loop was posted
  bool stopping_ = false;                     // guarded by mutex_

  // The current loop (written by the caller before the generation is bumped).
  const Body* body_ = nullptr;
  std::size_t count_ = 0;
  std::size_t grain_ = 1;
  struct alignas(64) Share {
    std::atomic<std::uint64_t> range{0};  // chunks [front, back) not yet taken (see pack)
  };
  std::unique_ptr<Share[]> shares_;      // per thread, the caller's first
  std::atomic<int> busy_{0};             // workers still in the current loop
  std::atomic<std::int64_t> gap_ns_{0};  // smoothed time between loops, ns (the spin budget)
  std::int64_t last_end_ns_ = 0;         // caller only: when the last loop ended, ns
  std::exception_ptr error_;             // guarded by mutex_
};

// A thread pool held by value, for objects that are copied (a World): a copy starts a pool of
// its own with as many threads, since a pool keeps nothing between loops. One thread needs no
// pool at all (get() is null).
class OwnedThreadPool {
 public:
  explicit OwnedThreadPool(int threads = 1)
      : pool_(threads > 1 ? std::make_unique<ThreadPool>(threads) : nullptr) {}
  OwnedThreadPool(const OwnedThreadPool& other) : OwnedThreadPool(other.size()) {}
  OwnedThreadPool& operator=(const OwnedThreadPool& other) {
    if (this != &other && other.size() != size()) *this = OwnedThreadPool(other.size());
    return *this;
  }
  OwnedThreadPool(OwnedThreadPool&&) noexcept = default;
  OwnedThreadPool& operator=(OwnedThreadPool&&) noexcept = default;
  ~OwnedThreadPool() = default;

  ThreadPool* get() const { return pool_.get(); }
  int size() const { return pool_ ? pool_->size() : 1; }

 private:
  std::unique_ptr<ThreadPool> pool_;
};

// The number of CPUs this process may run on: its affinity mask, and the cgroup's CPU quota
// (cpu.max, as under Slurm, Kubernetes or a container), whichever is smaller; at least 1. Not
// the machine's core count, which a job sharing the machine must not assume.
int available_cpus();

}  // namespace rugosim
