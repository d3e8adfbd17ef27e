#include "engine/core/thread_pool.h"

#include <atomic>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace rugosim {
namespace {

// Every index is visited exactly once, by a thread of the pool, whatever the count and grain.
TEST(ThreadPool, VisitsEveryIndexOnce) {
  for (const int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.size(), threads);
    for (const std::size_t count : {0u, 1u, 7u, 64u, 1000u}) {
      for (const std::size_t grain : {1u, 3u, 100u}) {
        std::vector<std::atomic<int>> visits(count);
        std::atomic<int> bad_thread{0};
        pool.parallel_for(count, grain, [&](std::size_t begin, std::size_t end, int thread) {
          if (thread < 0 || thread >= threads || end - begin > grain) ++bad_thread;
          for (std::size_t i = begin; i < end; ++i)
            ++visits[i];
        });
        for (std::size_t i = 0; i < count; ++i)
          ASSERT_EQ(visits[i].load(), 1) << threads << " threads, index " << i;
        EXPECT_EQ(bad_thread.load(), 0);
      }
    }
  }
}

// Each thread works through its own share from the front, then takes what is left of another's
// from the back: here the caller holds its first chunk until every other index is done, so the
// worker must do its own half (4 to 7) and then the caller's from the back (3, 2, 1). Under the
// old scheme (the next chunk to whichever thread was free) it would take 1, 2, 3 ... instead.
TEST(ThreadPool, AThreadDoneWithItsShareTakesTheRestOfAnotherFromTheBack) {
  ThreadPool pool(2);
  constexpr std::size_t kCount = 8;
  std::vector<std::size_t> worker_order;  // written by the worker alone
  std::atomic<std::size_t> done{0};
  bool waited_out = false;
  pool.parallel_for(kCount, 1, [&](std::size_t begin, std::size_t, int thread) {
    if (thread == 1) worker_order.push_back(begin);
    if (begin == 0) {
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
      while (done.load() < kCount - 1) {
        if (std::chrono::steady_clock::now() > until) {
          waited_out = true;
          break;
        }
        std::this_thread::yield();
      }
    } else {
      ++done;
    }
  });
  ASSERT_FALSE(waited_out) << "the caller's other chunks were never taken";
  // The caller's first take is always chunk 0 (and it waits there); if it came too late for
  // even that one, the worker did it last.
  const std::vector<std::size_t> expected{4, 5, 6, 7, 3, 2, 1};
  ASSERT_GE(worker_order.size(), expected.size());
  EXPECT_EQ(std::vector<std::size_t>(worker_order.begin(), worker_order.begin() + 7), expected);
}

// Many short loops back to back (as the World runs one per step): every one complete before
// the next, with the workers spinning or asleep in between.
TEST(ThreadPool, ManyShortLoopsInARow) {
  ThreadPool pool(3);
  std::vector<long> slots(257);
  long expected = 0;
  for (int loop = 0; loop < 3000; ++loop) {
    pool.parallel_for(slots.size(), 8, [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t i = begin; i < end; ++i)
        slots[i] += static_cast<long>(i);
    });
    expected += 1;
    if (loop % 1000 == 999) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  for (std::size_t i = 0; i < slots.size(); ++i)
    ASSERT_EQ(slots[i], expected * static_cast<long>(i));
}

// An exception in any chunk reaches the caller, after the loop has finished, and the pool
// still works afterwards.
TEST(ThreadPool, RethrowsAnExceptionOfTheBody) {
  ThreadPool pool(2);
  std::atomic<int> done{0};
  EXPECT_THROW(pool.parallel_for(100, 1,
                                 [&](std::size_t begin, std::size_t, int) {
                                   ++done;
                                   if (begin == 37) throw std::runtime_error("chunk 37");
                                 }),
               std::runtime_error);
  EXPECT_EQ(done.load(), 100);
  std::atomic<int> again{0};
  pool.parallel_for(10, 1, [&](std::size_t, std::size_t, int) { ++again; });
  EXPECT_EQ(again.load(), 10);
}

// A copy of a held pool has a pool of its own with as many threads.
TEST(OwnedThreadPool, CopiesStartTheirOwnPool) {
  const OwnedThreadPool one(1);
  EXPECT_EQ(one.get(), nullptr);
  EXPECT_EQ(one.size(), 1);
  const OwnedThreadPool three(3);
  const OwnedThreadPool copy = three;
  ASSERT_NE(copy.get(), nullptr);
  EXPECT_NE(copy.get(), three.get());
  EXPECT_EQ(copy.size(), 3);
  OwnedThreadPool assigned(1);
  assigned = three;
  EXPECT_EQ(assigned.size(), 3);
}

// The CPUs this process may use: at least one, and no more than the machine has.
TEST(AvailableCpus, IsBetweenOneAndTheMachine) {
  const int cpus = available_cpus();
  EXPECT_GE(cpus, 1);
  const unsigned machine = std::thread::hardware_concurrency();
  if (machine > 0) {
    EXPECT_LE(cpus, static_cast<int>(machine));
  }
}

}  // namespace
}  // namespace rugosim
