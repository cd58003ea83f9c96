// Unsaved changes left behind by a session that ended without cleaning up (a crash), for the tests of
// autosave and recovery: a child process opens `scene`, moves the front plane to `front`, autosaves
// into `stateDir` and ends without removing its file. Header-only: the suites that use it link the
// document's library (app/document/), which tests/support/'s library does not.
#pragma once

#include "app/document/autosave.h"
#include "io/scene_io.h"

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace vplab::test {

/// The recovery file the ended session left; empty when the child failed.
inline std::filesystem::path crashWithUnsavedFront(const std::filesystem::path& stateDir, const std::filesystem::path& scene,
                                                   double front) {
  const pid_t child = ::fork();
  if (child == 0) {
    Document doc(loadScene(scene));
    doc.scene().camera.front = front;
    doc.endFrame(false);
    Autosave a(stateDir, 0);
    a.writeNow(doc);
    ::_exit(a.error().empty() ? 0 : 1);
  }
  int status = 0;
  if (child < 0 || ::waitpid(child, &status, 0) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
  return stateDir / ("recovery-" + std::to_string(child) + ".json");
}

}  // namespace vplab::test
