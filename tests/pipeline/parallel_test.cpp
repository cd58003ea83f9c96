// pipeline/parallel.h: the chunks of shared work, each once, on every core at the caller's priority.
#include "pipeline/parallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace vplab {
namespace {

int niceOfThisThread() { return getpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid))); }

TEST(Parallel, EveryChunkRunsOnceOnEveryCoreAndOnOne) {
  for (bool parallel : {false, true}) {
    for (size_t chunks : {size_t(0), size_t(1), size_t(2), size_t(1000)}) {
      std::vector<std::atomic<int>> runs(chunks);
      forEachChunk(chunks, parallel, [&](size_t k) { ++runs[k]; });
      EXPECT_TRUE(std::all_of(runs.begin(), runs.end(), [](const std::atomic<int>& n) { return n == 1; }))
          << chunks << " chunks, parallel " << parallel;
    }
  }
  std::vector<size_t> order;
  forEachChunk(5, false, [&](size_t k) { order.push_back(k); });
  EXPECT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 4})) << "one core: in order";
}

TEST(Parallel, AnExceptionInAChunkReachesTheCaller) {
  for (bool parallel : {false, true})
    EXPECT_THROW(forEachChunk(64, parallel,
                              [](size_t k) {
                                if (k == 40) throw std::runtime_error("chunk 40");
                              }),
                 std::runtime_error);
}

// The window's pipeline worker runs at nice 5 (app/workers/background_priority.h): the threads that
// help it must not take the window's core at nice 0. The pool is made first by this thread (its
// threads start at its priority, as when the viewer ran something on its own thread first); chunks
// that sleep make every thread of the pool join in.
TEST(Parallel, HelpersRunAtTheCallersPriority) {
  ASSERT_TRUE(parallelAvailable());
  if (parallelThreads() < 2) GTEST_SKIP() << "one core: no helper";
  const int ownNice = niceOfThisThread();
  std::mutex m;
  std::set<std::thread::id> threads;
  std::vector<int> nices;
  auto record = [&](size_t) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));  // long enough for a busy machine to wake a helper
    std::lock_guard lock(m);
    threads.insert(std::this_thread::get_id());
    nices.push_back(niceOfThisThread());
  };
  forEachChunk(64, true, record);
  ASSERT_GT(threads.size(), 1u) << "a helper joined in";
  for (int n : nices) ASSERT_EQ(n, ownNice) << "the pool's threads start at this thread's priority";
  threads.clear();
  nices.clear();
  int callerNice = 0;
  std::thread caller([&] {
    callerNice = std::min(19, ownNice + 5);
    ASSERT_EQ(setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), callerNice), 0);
    forEachChunk(64, true, record);
  });
  caller.join();
  EXPECT_GT(threads.size(), 1u) << "a helper joined in";
  for (int n : nices) EXPECT_EQ(n, callerNice);
}

}  // namespace
}  // namespace vplab
