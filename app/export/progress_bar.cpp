#include "app/export/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <iostream>

namespace vplab {

ProgressBar::ProgressBar(std::string what, std::string done)
    : what_(std::move(what)), doneWord_(std::move(done)), terminal_(isatty(STDERR_FILENO) != 0) {}

void ProgressBar::operator()(size_t done, size_t total) {
  if (terminal_) {
    const int width = 30, filled = int(width * done / std::max<size_t>(total, 1));
    std::cerr << "\r" << what_ << ": [" << std::string(size_t(filled), '#') << std::string(size_t(width - filled), '.')
              << "] " << done << "/" << total << (done == total ? "\n" : "") << std::flush;
  } else if (size_t tenth = 10 * done / std::max<size_t>(total, 1); tenth > lastTenth_ || done == total) {
    lastTenth_ = tenth;
    std::cerr << what_ << ": " << done << "/" << total << " " << doneWord_ << "\n";
  }
}

namespace {
std::atomic<int> gStopRequested{0};  // set by the handler, read by StopRequests::requested
extern "C" void onStopSignal(int) { gStopRequested.store(1); }
}  // namespace

struct StopRequests::Saved {
  struct sigaction interrupt, terminate;
};

StopRequests::StopRequests() : saved_(new Saved) {
  gStopRequested.store(0);
  struct sigaction sa {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &saved_->interrupt);
  sigaction(SIGTERM, &sa, &saved_->terminate);
}

StopRequests::~StopRequests() {
  sigaction(SIGINT, &saved_->interrupt, nullptr);
  sigaction(SIGTERM, &saved_->terminate, nullptr);
  delete saved_;
}

bool StopRequests::requested() const { return gStopRequested.load() != 0; }

}  // namespace vplab
