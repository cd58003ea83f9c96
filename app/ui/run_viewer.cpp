// The window's event loop. It sleeps in glfwWaitEventsTimeout until input arrives or the viewer
// asks for a frame (Viewer::wakeIn: an animation, ImGui settling after a change, the text cursor,
// the next autosave), so an idle window uses no CPU. Input goes through an InputQueue (one button
// or key transition per frame: no click is lost). SIGTERM, SIGINT and SIGHUP (the terminal closed)
// write the recovery file of unsaved changes before the viewer ends.
#include "app/ui/run_viewer.h"

#include "app/context/context_glfw.h"
#include "app/document/assets.h"
#include "app/document/autosave.h"
#include "app/document/preferences.h"
#include "app/gl/render_target.h"
#include "app/ui/window_input.h"
#include "app/ui/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>  // ImGui_ImplGlfw_NewFrame

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <atomic>
#include <ctime>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

namespace vplab {

namespace {

constexpr double kLongestWait = 60.0;   // glfwWaitEventsTimeout needs a finite timeout
constexpr int kSettleFrames = 3;        // ImGui shows the effect of input (hover, popups) over ~2 frames

// The only process-wide state: a signal handler can reach nothing else. The handler does only
// async-signal-safe things (an atomic store, write(2)); a watcher thread turns the byte on the
// pipe into glfwPostEmptyEvent (thread-safe in GLFW), which wakes the event wait at once.
std::atomic<int> gSignal{0};
std::atomic<int> gWakeFd{-1};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void onEndSignal(int sig) {
  const int saved = errno;
  gSignal.store(sig);
  const int fd = gWakeFd.load();
  if (fd >= 0) {
    const char byte = 's';
    [[maybe_unused]] const ssize_t n = ::write(fd, &byte, 1);
  }
  errno = saved;
}

class EndSignals {
 public:
  EndSignals() {
    if (::pipe2(fds_, O_CLOEXEC) != 0) fds_[0] = fds_[1] = -1;
    gSignal.store(0);
    gWakeFd.store(fds_[1]);
    if (fds_[0] >= 0)
      watcher_ = std::thread([fd = fds_[0]] {
        for (char byte = 0;;) {
          const ssize_t n = ::read(fd, &byte, 1);
          if (n < 0 && errno == EINTR) continue;
          if (n <= 0 || byte == 'q') return;
          glfwPostEmptyEvent();
        }
      });
    struct sigaction sa {};
    sa.sa_handler = onEndSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    ::sigaction(SIGTERM, &sa, &oldTerm_);
    ::sigaction(SIGINT, &sa, &oldInt_);
    ::sigaction(SIGHUP, &sa, &oldHup_);
  }
  ~EndSignals() {
    ::sigaction(SIGTERM, &oldTerm_, nullptr);
    ::sigaction(SIGINT, &oldInt_, nullptr);
    ::sigaction(SIGHUP, &oldHup_, nullptr);
    gWakeFd.store(-1);
    if (watcher_.joinable()) {
      const char byte = 'q';
      [[maybe_unused]] const ssize_t n = ::write(fds_[1], &byte, 1);
      watcher_.join();
    }
    for (int fd : fds_)
      if (fd >= 0) ::close(fd);
  }
  EndSignals(const EndSignals&) = delete;
  EndSignals& operator=(const EndSignals&) = delete;
  int received() const { return gSignal.load(); }

 private:
  int fds_[2] = {-1, -1};
  std::thread watcher_;
  struct sigaction oldTerm_ {}, oldInt_ {}, oldHup_ {};
};

/// "the world and NPC views were not ready after 30 s".
std::string describeNotReady(const std::vector<ViewKind>& late, double seconds) {
  std::string names;
  for (size_t i = 0; i < late.size(); ++i) {
    if (i > 0) names += i + 1 == late.size() ? " and " : ", ";
    names += std::string(toString(late[i]));
  }
  std::ostringstream out;
  out << "the " << names << (late.size() == 1 ? " view was" : " views were") << " not ready after " << seconds
      << " s (still drawn on the render thread)";
  return out.str();
}

std::string screenshotName() {
  const std::time_t now = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "vplab-%Y%m%d-%H%M%S.png", std::localtime(&now));
  return buf;
}

/// The event loop; returns the exit status.
int loop(GlfwWindow& window, Viewer& viewer, WindowInput& input, const EndSignals& signals, const ViewerLaunch& launch);

}  // namespace

int runViewerWindow(ViewerLaunch launch) {
  const std::string title = "vplab";
  GlfwWindow window(launch.width, launch.height, title, launch.glDebug);
  if (const std::filesystem::path icon = iconFile(); !icon.empty()) {
    try {
      const Image image = readPng(icon);
      static_assert(sizeof(Rgba) == 4);  // RGBA8, top row first: what GLFW takes
      if (!image.empty()) window.setIcon(image.width, image.height, &image.pixels.front().r);
    } catch (const std::exception& e) {
      std::cerr << "vplab: the window has no icon (" << e.what() << ")\n";
    }
  }
  Viewer viewer(window, std::move(launch.scene), launch.uiScale);
  // The language: --lang, else View > Language's last choice, else the locale's; a choice in the
  // menu is remembered for the next start.
  const std::filesystem::path preferencesFile = defaultPreferencesFile();
  std::string preferencesProblem;
  const Preferences preferences = readPreferences(preferencesFile, &preferencesProblem);
  if (!preferencesProblem.empty()) std::cerr << "vplab: " << preferencesProblem << "\n";
  Session::Start start{.language = startLanguage(launch.language, preferences)};
  if (!preferencesFile.empty())
    start.rememberLanguage = [preferencesFile, preferences](Language lang) {
      Preferences p = preferences;
      p.language = lang;
      writePreferences(preferencesFile, p);
    };
  GlfwBackend backend(window.handle());
  // glfwPostEmptyEvent is thread-safe: a finished run or view image wakes the event wait.
  viewer.run().useWorker([] { glfwPostEmptyEvent(); });
  try {
    viewer.images().useWorker(window.createShared(), [] { glfwPostEmptyEvent(); });
  } catch (const std::exception& e) {
    std::cerr << "vplab: the views are drawn in the window's thread (" << e.what() << ")\n";
  }
  WindowInput input(window.handle());
  EndSignals signals;
  start.autosaveDirectory = Autosave::defaultDirectory();
  if (!start.autosaveDirectory.empty()) {
    start.recoveries = Autosave::findAll(start.autosaveDirectory);
    for (const Recovery& r : start.recoveries)
      std::cerr << "vplab: " << r.file.string() << " holds unsaved changes of "
                << (r.scenePath.empty() ? std::string("the default lecture scene") : r.scenePath.string())
                << " from a session that did not end normally; the viewer offers to recover them\n";
  }
  // An exercise's answers are kept beside the recovery files, one per exercise (app/session/exercises.h).
  if (!start.autosaveDirectory.empty()) start.answers = AnswerShelf::inDirectory(start.autosaveDirectory / "answers");
  viewer.session().start(std::move(start));
  if (!launch.lesson.empty()) viewer.session().openLesson(launch.lesson, launch.lessonStep);
  if (!launch.exercise.empty()) viewer.session().exercises().openFolder(launch.exercise, launch.reveal);
  try {
    const int status = loop(window, viewer, input, signals, launch);
    // The views' render thread finishes the image it is drawing before the viewer ends (a GL draw
    // call cannot be interrupted): the window goes at once.
    glfwHideWindow(window.handle());
    return status;
  } catch (const std::exception& e) {
    // The window was open: no headless fallback now (it would write files nobody asked for). Keep
    // the work, say what happened, and end with a status that says it was no normal end.
    const std::filesystem::path kept = viewer.session().recovery().writeRecoveryNow();
    std::cerr << "vplab: the viewer ended unexpectedly: " << e.what();
    if (!kept.empty()) std::cerr << "; the unsaved changes are kept in " << kept.string() << " and offered at the next start";
    std::cerr << "\n";
    return kUnexpectedEnd;
  }
}

namespace {

int loop(GlfwWindow& window, Viewer& viewer, WindowInput& input, const EndSignals& signals, const ViewerLaunch& launch) {
  std::string shownTitle;
  int frames = 0;
  // Since when (glfwGetTime(), s) a screenshot or the scripted end waits for the views; < 0: not waiting.
  // (A plain double: GCC 12 warns falsely of an uninitialised std::optional<double> here.)
  double waitingSince = -1;
  // --report-frames: the longest frame, and the longest of those that answered input after the first
  // (what a user sees as a pause after a key or a drag), in seconds from the frame's start to the swap.
  double longestFrame = 0, longestAnswer = 0;
  auto report = [&] {
    if (launch.reportFrames)
      std::cerr << "vplab: " << frames << " frames drawn, the longest in " << std::lround(longestFrame * 1000)
                << " ms, the longest answering input in " << std::lround(longestAnswer * 1000) << " ms\n";
  };
  double lastFrame = 0;
  bool driverDone = false;
  for (;;) {
    const bool scriptedEnd = launch.quitAfterFrames > 0 && frames >= launch.quitAfterFrames;
    // Smoke tests, scripted screenshots (--quit-after-frames) and a driver draw every frame, as fast
    // as vsync; past their count they wait, as an idle window does, for the render thread's images.
    const bool continuous = (launch.quitAfterFrames > 0 && !scriptedEnd) || launch.driver;
    const double wait = continuous || input.changed || !input.queue.empty() ? 0 : viewer.wakeIn();
    // wakeIn() counts from the last frame's time, which stands still while no frame is drawn: the
    // timer's end is kept here in real time (the next autosave, the text cursor's blink).
    const double timerEnd = glfwGetTime() + std::min(wait, kLongestWait);
    if (wait <= 0) glfwPollEvents();
    else glfwWaitEventsTimeout(std::min(wait, kLongestWait));
    if (const int sig = signals.received()) {
      const std::filesystem::path kept = viewer.session().recovery().writeRecoveryNow();
      std::cerr << "vplab: ended by " << (sig == SIGTERM ? "SIGTERM" : sig == SIGINT ? "SIGINT" : "SIGHUP");
      if (!kept.empty()) std::cerr << "; the unsaved changes are kept in " << kept.string() << " and offered at the next start";
      std::cerr << "\n";
      report();
      return 128 + sig;
    }
    if (window.shouldClose()) {
      viewer.requestQuit();  // asks first when the scene has unsaved changes
      window.setShouldClose(false);
      input.changed = true;
    }
    // A driver that is done ends the viewer as quitting does: the next frame is the last (with its
    // screenshot, when one is asked for on quitting).
    if (launch.driver && !driverDone && !launch.driver(viewer, input.queue, window, lastFrame)) driverDone = true;
    const bool answering = input.changed || !input.queue.empty();
    if (answering) viewer.requestFrames(kSettleFrames);
    input.changed = false;
    if (!continuous && viewer.wakeIn() > 0 && glfwGetTime() < timerEnd) continue;  // woken for nothing that shows

    const double frameStart = glfwGetTime();
    viewer.makeCurrent();
    ImGui_ImplGlfw_NewFrame();
    input.queue.feed(ImGui::GetIO());
    int w = 0, h = 0;
    window.framebufferSize(w, h);
    if (w > 0 && h > 0) viewer.frame(0, w, h);
    ++frames;
    const bool scripted = launch.quitAfterFrames > 0 && frames >= launch.quitAfterFrames;
    const bool quitting = viewer.shouldQuit() || scripted || driverDone;
    const bool shot = viewer.screenshotRequested() || (quitting && !launch.screenshotOnQuit.empty());
    // A screenshot is of what the user asked to see, and a scripted end shows it too: both wait until
    // every shown view has its current image (docs/lecturers.md "The viewer", issue 19).
    if (shot || scripted) {
      if (const std::vector<ViewKind> late = viewer.viewsNotReady(); !late.empty()) {
        if (waitingSince < 0) waitingSince = glfwGetTime();
        if (glfwGetTime() - waitingSince < launch.waitForViews) {
          window.swapBuffers();
          continue;  // the render thread wakes the wait when an image is finished
        }
        const std::string why = describeNotReady(late, launch.waitForViews);
        waitingSince = -1;
        if (quitting) {
          std::cerr << "vplab: " << why << (shot ? "; no screenshot written" : "") << "\n";
          viewer.session().recovery().endSession();
          report();
          return 1;
        }
        viewer.screenshotFailed(why);
      } else if (shot) {
        waitingSince = -1;
        const std::string file = viewer.screenshotRequested() ? screenshotName() : launch.screenshotOnQuit;
        try {
          writePng(gl::readPixels(window.gl(), 0, w, h), file);
          viewer.screenshotTaken(file);
        } catch (const std::exception& e) {  // a read-only working directory, a full disk: said, not fatal
          if (!viewer.screenshotRequested()) throw;
          viewer.screenshotFailed(e.what());
        }
      }
    }
    window.swapBuffers();
    lastFrame = glfwGetTime() - frameStart;
    longestFrame = std::max(longestFrame, lastFrame);
    if (answering && frames > 1) longestAnswer = std::max(longestAnswer, glfwGetTime() - frameStart);
    if (viewer.title() != shownTitle) window.setTitle(shownTitle = viewer.title());
    if (quitting) break;
  }
  viewer.session().recovery().endSession();
  report();
  return 0;
}

}  // namespace

}  // namespace vplab
