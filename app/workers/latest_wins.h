// The skeleton of the viewer's two workers, the CPU pipeline's (pipeline_worker.h) and the views' render
// thread (app/render/view_worker.h): one thread that does, for each of a fixed number of slots (one
// pipeline; one slot per view), only the latest request. A request replaces its slot's request not yet
// started (the latest camera wins: no queue of stale work); the thread takes the slot asked longest
// ago first, does the work with the lock released and publishes the result, which the window takes
// when it draws its next frame. Tickets grow, so the window can wait for the answer to one request.
//
// The owner's bookkeeping of what a job may use (the pipeline's runs to reuse, the views' image
// buffers) runs under the skeleton's lock, in the callbacks that next(), finish() and take() take.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace vplab {

template <class Request, class Result>
class LatestWins {
 public:
  /// A request taken by the thread.
  struct Job {
    size_t slot = 0;
    uint64_t ticket = 0;
    Request request;
  };

  /// `wake` is called on the thread after each result is published (glfwPostEmptyEvent).
  LatestWins(size_t slots, std::function<void()> wake) : slots_(slots), wake_(std::move(wake)) {}
  /// Stops the thread (see stop()).
  ~LatestWins() { stop(); }
  LatestWins(const LatestWins&) = delete;
  LatestWins& operator=(const LatestWins&) = delete;

  /// Starts the thread: `body` calls next() and finish() until next() returns nothing.
  void start(std::function<void()> body) { thread_ = std::thread(std::move(body)); }
  /// Lets the job under way finish (work cannot be interrupted), then ends the thread. The owner
  /// calls it first in its destructor, while what the body uses still exists.
  void stop() {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

  /// Asks for work in `slot`; replaces the slot's request not yet started. Returns its ticket.
  uint64_t request(size_t slot, Request r) {
    std::lock_guard lock(mutex_);
    Slot& s = slots_.at(slot);
    s.pending = std::move(r);
    s.pendingTicket = nextTicket_++;
    changed_.notify_all();
    return s.pendingTicket;
  }

  /// The newest result of `slot` published since the last call, waiting up to `seconds` for the one
  /// answering `ticket`; `underLock` sees it first, with the lock held.
  std::optional<Result> take(size_t slot, uint64_t ticket, double seconds,
                             const std::function<void(const Result&)>& underLock = {}) {
    std::unique_lock lock(mutex_);
    Slot& s = slots_.at(slot);
    if (seconds > 0)
      changed_.wait_for(lock, std::chrono::duration<double>(seconds),
                        [&] { return stop_ || (s.finished && s.finishedTicket >= ticket); });
    if (s.finished && underLock) underLock(*s.finished);
    return std::exchange(s.finished, std::nullopt);
  }

  /// Whether a result of `slot` is published and not yet taken (the window then draws at once).
  bool hasFinished(size_t slot) const {
    std::lock_guard lock(mutex_);
    return slots_.at(slot).finished.has_value();
  }

  /// `f()` with the lock held: the owner's bookkeeping read from another thread.
  template <class F>
  auto locked(F&& f) const {
    std::lock_guard lock(mutex_);
    return f();
  }

  /// How many results the thread has published.
  unsigned published() const {
    std::lock_guard lock(mutex_);
    return published_;
  }

  // ---------------------------------------------------------------- for the thread's body

  /// Waits for a request and takes the one of the slot asked longest ago; nothing once stopping.
  /// `underLock` sees the job first, with the lock held.
  std::optional<Job> next(const std::function<void(const Job&)>& underLock = {}) {
    std::unique_lock lock(mutex_);
    Slot* oldest = nullptr;
    changed_.wait(lock, [&] {
      oldest = nullptr;
      for (Slot& s : slots_)
        if (s.pending && (!oldest || s.pendingTicket < oldest->pendingTicket)) oldest = &s;
      return stop_ || oldest;
    });
    if (stop_) return std::nullopt;
    Job job{size_t(oldest - slots_.data()), oldest->pendingTicket, std::move(*oldest->pending)};
    oldest->pending.reset();
    if (underLock) underLock(job);
    return job;
  }

  /// Publishes the result of `job`, the slot's newest (a result not yet taken is replaced);
  /// `underLock` runs first, with the lock held. Then wakes the window.
  void finish(const Job& job, Result result, const std::function<void()>& underLock = {}) {
    {
      std::lock_guard lock(mutex_);
      if (underLock) underLock();
      Slot& s = slots_[job.slot];
      s.finished = std::move(result);
      s.finishedTicket = job.ticket;
      ++published_;
    }
    changed_.notify_all();
    if (wake_) wake_();
  }

 private:
  struct Slot {
    std::optional<Request> pending;
    uint64_t pendingTicket = 0;
    std::optional<Result> finished;  // not yet taken
    uint64_t finishedTicket = 0;
  };
  std::vector<Slot> slots_;
  std::function<void()> wake_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  bool stop_ = false;
  uint64_t nextTicket_ = 1;
  unsigned published_ = 0;
  std::thread thread_;
};

}  // namespace vplab
