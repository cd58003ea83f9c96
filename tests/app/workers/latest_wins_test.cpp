// The workers' skeleton (app/workers/latest_wins.h): per slot only the latest request is done, the slot
// asked longest ago first; take() waits for the answer to a ticket; the owner's callbacks run under
// the lock; stopping ends the thread with requests left undone.
#include "app/workers/latest_wins.h"

#include <gtest/gtest.h>

#include <atomic>
#include <utility>
#include <vector>

namespace vplab {
namespace {

using Queue = LatestWins<int, int>;

TEST(LatestWins, TheLatestRequestOfASlotWinsAndTheSlotAskedLongestAgoGoesFirst) {
  std::atomic<int> wakes = 0;
  Queue q(2, [&] { ++wakes; });
  // Asked before the thread starts, so the order the thread sees is fixed.
  const uint64_t first = q.request(1, 5);
  const uint64_t other = q.request(0, 7);
  const uint64_t latest = q.request(1, 6);  // replaces 5, not yet started
  EXPECT_LT(first, other);
  EXPECT_LT(other, latest);
  std::vector<std::pair<size_t, int>> done;  // the thread's own until it is stopped
  std::vector<int> seenUnderLock;
  q.start([&] {
    while (auto job = q.next([&](const Queue::Job& j) { seenUnderLock.push_back(j.request); }))
      q.finish(*job, job->request * 10, [&] { done.emplace_back(job->slot, job->request); });
  });
  EXPECT_EQ(q.take(1, latest, 10), std::optional<int>(60));
  EXPECT_EQ(q.take(0, other, 10), std::optional<int>(70));
  EXPECT_EQ(q.take(0, other, 0), std::nullopt) << "a result is taken once";
  EXPECT_FALSE(q.hasFinished(0));
  q.stop();
  EXPECT_EQ(done, (std::vector<std::pair<size_t, int>>{{0, 7}, {1, 6}})) << "5 was replaced; slot 0 was asked first";
  EXPECT_EQ(seenUnderLock, (std::vector<int>{7, 6}));
  EXPECT_EQ(q.published(), 2u);
  EXPECT_EQ(wakes, 2);
}

TEST(LatestWins, TakeWaitsForItsTicketAndTheUnderLockCallbackSeesTheResult) {
  Queue q(1, {});
  q.start([&] {
    while (auto job = q.next()) q.finish(*job, job->request + 1);
  });
  for (int i = 0; i < 50; ++i) {
    const uint64_t ticket = q.request(0, i);
    int seen = -1;
    const std::optional<int> result = q.take(0, ticket, 10, [&](const int& r) { seen = r; });
    ASSERT_TRUE(result) << "request " << i << " not answered within 10 s";
    // The answer may be to an earlier request only if it was published before ours: waiting for the
    // ticket means the newest is ours.
    EXPECT_EQ(*result, i + 1);
    EXPECT_EQ(seen, i + 1);
  }
  EXPECT_EQ(q.published(), 50u);
  EXPECT_EQ(q.locked([] { return 42; }), 42) << "locked() runs its function and returns its value";
}

TEST(LatestWins, StoppingLeavesPendingRequestsUndoneAndAQueueNeverStartedEndsQuietly) {
  {
    Queue never(3, {});
    never.request(2, 1);
  }  // no thread: nothing to join
  Queue q(1, {});
  std::atomic<int> jobs = 0;
  q.start([&] {
    while (auto job = q.next()) {
      ++jobs;
      q.finish(*job, 0);
    }
  });
  q.stop();
  q.request(0, 1);  // after the stop: never done
  q.stop();         // a second stop is harmless
  EXPECT_EQ(jobs, 0);
  EXPECT_EQ(q.take(0, 1, 0.05), std::nullopt) << "take does not wait on a stopped queue";
}

}  // namespace
}  // namespace vplab
