#include "pipeline/parallel.h"

#include <cerrno>
#include <thread>

#ifdef VPLAB_HAVE_TBB
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace vplab {

#ifdef VPLAB_HAVE_TBB
namespace {

// Linux gives each thread its own nice value, and the window's helpers run below the window
// (app/workers/background_priority.h). The threads that share a helper's work must run below it
// too, or a run on every core would take the window's core from it. So each chunk runs at the nice
// value of the thread that shared the work out.
#ifdef SYS_gettid
constexpr int kNiceUnknown = 100;  // no nice value is this (they run from -20 to 19)

int niceOfThisThread() {
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)));
  return errno ? kNiceUnknown : nice;
}

// The value is remembered by the thread itself, so that a chunk costs no system call while the
// callers' priority stays the same. A nice value once raised is not lowered again: an ordinary user
// may not (RLIMIT_NICE), and the window's helpers only ever ask for more.
void runAtNice(int nice) {
  thread_local int current = kNiceUnknown;
  if (nice == kNiceUnknown || nice == current) return;
  if (setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), nice) == 0) current = nice;
}
#else
constexpr int kNiceUnknown = 0;
int niceOfThisThread() { return kNiceUnknown; }
void runAtNice(int) {}
#endif

}  // namespace
#endif

bool parallelAvailable() {
#ifdef VPLAB_HAVE_TBB
  return true;
#else
  return false;
#endif
}

unsigned parallelThreads() {
#ifdef VPLAB_HAVE_TBB
  return unsigned(tbb::this_task_arena::max_concurrency());
#else
  return 1;
#endif
}

void forEachChunk(size_t chunks, bool parallel, const std::function<void(size_t)>& body) {
#ifdef VPLAB_HAVE_TBB
  if (parallel && chunks > 1) {
    const int nice = niceOfThisThread();
    const std::thread::id caller = std::this_thread::get_id();
    // One task a chunk: the chunks are already the size worth a task (the callers' grains).
    tbb::parallel_for(size_t(0), chunks, [&](size_t k) {
      if (std::this_thread::get_id() != caller) runAtNice(nice);
      body(k);
    });
    return;
  }
#endif
  (void)parallel;
  for (size_t k = 0; k < chunks; ++k) body(k);
}

}  // namespace vplab
