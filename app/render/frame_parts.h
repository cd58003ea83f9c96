// Where a frame's own time goes, part by part (issue 42: no frame of the page's over 50 ms; docs/measured.md
// "Large scenes in the page"). The page hands each part to the browser as a User Timing measure
// ("vplab part: <name>", page.cpp), so its profiler and the browser test see which part made a frame
// long. The window and the headless commands set no sink: nothing is timed there.
#pragma once

#include <chrono>
#include <functional>
#include <utility>

namespace vplab {

class FrameParts {
 public:
  /// Receives a part's name (a string literal) and how long it took, in seconds, when it ends.
  using Sink = std::function<void(const char* part, double seconds)>;

  void setSink(Sink sink) { sink_ = std::move(sink); }

  /// Times the scope it lives in as `part` (nothing without a sink).
  class Timed {
   public:
    Timed(const Sink* sink, const char* part) : sink_(sink), part_(part) {
      if (sink_) start_ = std::chrono::steady_clock::now();
    }
    ~Timed() {
      if (sink_) (*sink_)(part_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    }
    Timed(const Timed&) = delete;
    Timed& operator=(const Timed&) = delete;

   private:
    const Sink* sink_;
    const char* part_;
    std::chrono::steady_clock::time_point start_;
  };

  [[nodiscard]] Timed time(const char* part) const { return Timed(sink_ ? &sink_ : nullptr, part); }

 private:
  Sink sink_;
};

}  // namespace vplab
