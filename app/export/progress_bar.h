// Progress of long work on the command line (`vplab grade batch`, `vplab render --lesson`): a bar
// redrawn in place on a terminal, a line every tenth otherwise (a log), on stderr. And Ctrl+C as a
// request to stop cleanly (no half-written file), rather than an abrupt end.
#pragma once

#include <cstddef>
#include <string>

namespace vplab {

class ProgressBar {
 public:
  /// `what` prefixes each line ("vplab grade batch"), `done` names what was counted ("graded").
  ProgressBar(std::string what, std::string done);
  /// `done` of `total` are finished.
  void operator()(size_t done, size_t total);

 private:
  std::string what_, doneWord_;
  bool terminal_;
  size_t lastTenth_ = 0;
};

/// While it lives, SIGINT (Ctrl+C) and SIGTERM only set a flag that requested() reads, so that the
/// work can stop at its next step and remove what it had half written; the handlers before are put
/// back at its end. (A signal handler can reach only a static flag: the one static of this file.)
class StopRequests {
 public:
  StopRequests();
  ~StopRequests();
  StopRequests(const StopRequests&) = delete;
  StopRequests& operator=(const StopRequests&) = delete;
  bool requested() const;

 private:
  struct Saved;
  Saved* saved_;
};

}  // namespace vplab
