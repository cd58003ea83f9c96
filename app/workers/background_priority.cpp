#include "app/workers/background_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace vplab {

void runBelowTheWindow() {
#ifdef SYS_gettid
  constexpr int kNice = 5;
  setpriority(PRIO_PROCESS, pid_t(syscall(SYS_gettid)), kNice);
#endif
}

}  // namespace vplab
