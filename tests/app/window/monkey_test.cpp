// The monkey test of the real window (issue 37: "the lecture never fails"). A seeded random user
// plays the viewer in a GLFW window under Xvfb, through the same input queue GLFW's callbacks fill:
// keys (the lesson's clicker keys, digits and Enter, the shortcuts, Escape, F11, F12), clicks and
// double-clicks anywhere and on every widget the viewer recorded, drags in the views and on the
// fields, fields typed into with invalid and extreme values ("nan", "1e308", "0,5", PRP on VRP),
// the wheel, window resizes, UI scales, both languages, every bundled lesson at random steps and
// every bundled scene. It fails when the viewer ends before the events are spent, when a frame ends
// in an error the viewer had to catch (an exception, a GL error, a view that failed), or when a
// frame takes over a second. Every run prints its seed; a failure prints how to replay it:
//   VPLAB_MONKEY_SEED=N VPLAB_MONKEY_EVENTS=M xvfb-run -a build/tests/test_monkey
// (the events are the seed's; the render thread's and the workers' timing is the machine's).
#include "app/context/context_glfw.h"
#include "app/document/assets.h"
#include "app/lessons/lesson.h"
#include "app/text/catalogue.h"
#include "app/ui/input_queue.h"
#include "app/ui/keys.h"
#include "app/ui/run_viewer.h"
#include "app/ui/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace vplab {
namespace {

namespace fs = std::filesystem;

/// A number from the environment, or `fallback`.
unsigned long envNumber(const char* name, unsigned long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::stoul(v) : fallback;
}

/// What a user types into a number field: ordinary values, the lecture's invalid cameras' numbers,
/// the extremes and what is no number at all.
const std::vector<std::string> kTyped = {"0",      "1",    "-1",    "8",     "7.5",   "0.5",  "-3/5", "0,5",  "1e308",
                                         "-1e308", "1e-320", "nan", "inf",   "-inf",  "abc",  "",     "-0",   "99999999999",
                                         "3.14159", "2",   "-2",    "1e5",   "0.0001", "12e",  "--1",  "+4",  "1..2"};

/// The keys a lecturer's clicker, keyboard and fingers reach (not Ctrl+Q: quitting is no failure).
const std::vector<int> kKeys = {keys::kRight, keys::kLeft,  keys::kSpace, keys::kPageDown, keys::kPageUp, keys::kHome,
                                keys::kEnd,   keys::kEnter, keys::kEscape, keys::kF1,      keys::kF11,    keys::kF12,
                                keys::kB,     keys::kC,     keys::kP,      keys::kR,       '0', '1', '2', '3', '4', '5',
                                '6', '7', '8', '9', 258 /* Tab */, 259 /* Backspace */, 261 /* Delete */};

class Monkey {
 public:
  static constexpr unsigned long kWarmUpFrames = 30;

  Monkey(unsigned seed, unsigned long events) : rng_(seed), events_(events) {
    for (Language lang : {Language::en, Language::de})
      for (const LessonFileInfo& l : listBundledLessons(lang)) lessons_.push_back(l.file);
    for (const SceneFileInfo& s : listPresetScenes()) scenes_.push_back(s.file);
  }

  /// The driver (ViewerDriver): checks the last frame, then acts when the queue has room.
  bool operator()(Viewer& viewer, InputQueue& queue, GlfwWindow& window, double lastFrame) {
    ++frames_;
    ++windowFrames_;
    // A quit is in reach when a menu or dialog is open (menus are ImGui popups) or one was asked for.
    quitInReach_ = viewer.state().quitRequested || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    if (viewer.caught().count > 0) return fail("the viewer caught an error: " + viewer.caught().last);
    // The first frames compile the shaders and build the font atlas (llvmpipe, no shader cache): the
    // user has not acted yet, and a lecturer sees them before the class does.
    if (windowFrames_ > kWarmUpFrames) {
      if (lastFrame > longest_) {
        longest_ = lastFrame;
        longestAfter_ = lastAction_;
      }
      if (lastFrame > 1.0) return fail("a frame took " + std::to_string(lastFrame) + " s");
    }
    if (queue.pending() > 6) return true;  // the viewer takes one transition a frame: let it catch up
    if (done_ >= events_) {
      finished_ = true;
      return false;
    }
    act(viewer, queue, window);
    return true;
  }

  /// The user quit (File ▸ Quit reached through an open menu, the dialog's "Quit without saving"):
  /// their right, so the viewer is started again and the monkey goes on, as the user would.
  void restarted() {
    ++restarts_;
    windowFrames_ = 0;
  }
  unsigned long restarts() const { return restarts_; }
  /// Whether the last frame showed a way to quit: a window that ends with status 0 without one did
  /// not end by the user's hand.
  bool quitInReach() const { return quitInReach_; }
  bool finished() const { return finished_; }
  const std::string& failure() const { return failure_; }
  unsigned long done() const { return done_; }
  unsigned long frames() const { return frames_; }
  double longest() const { return longest_; }
  const std::string& lastAction() const { return lastAction_; }
  const std::string& longestAfter() const { return longestAfter_; }

 private:
  bool fail(std::string why) {
    failure_ = std::move(why) + " (after " + std::to_string(done_) + " events; the last: " + lastAction_ + ")";
    return false;
  }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }

  /// A point anywhere in the window, or inside a widget the viewer recorded last frame.
  std::pair<double, double> somewhere(const Viewer& viewer, int w, int h, bool widget) {
    const auto& rects = viewer.rects().rects;
    if (widget && !rects.empty()) {
      auto it = rects.begin();
      std::advance(it, pick(int(rects.size())));
      const ImVec4& r = it->second;
      return {r.x + uniform(0.1, 0.9) * r.z, r.y + uniform(0.2, 0.8) * r.w};
    }
    return {uniform(0, w), uniform(0, h)};
  }
  /// Quitting is the user's right, not a failure: the monkey never clicks File ▸ Quit.
  bool onQuit(const Viewer& viewer, double x, double y) const {
    const auto it = viewer.rects().rects.find("menu.quit");
    if (it == viewer.rects().rects.end()) return false;
    const ImVec4& r = it->second;
    return x >= r.x - 2 && x <= r.x + r.z + 2 && y >= r.y - 2 && y <= r.y + r.w + 2;
  }
  void press(InputQueue& q, int key, bool ctrl = false) {
    if (ctrl) q.key(341 /* left Ctrl */, true);
    q.key(key, true);
    q.key(key, false);
    if (ctrl) q.key(341, false);
    done_ += ctrl ? 4 : 2;
  }
  void click(InputQueue& q, double x, double y, int button = 0, int times = 1) {
    q.mouseMove(x, y);
    for (int i = 0; i < times; ++i) {
      q.mouseButton(button, true);
      q.mouseButton(button, false);
    }
    done_ += 1 + 2 * times;
  }
  void type(InputQueue& q, const std::string& text) {
    for (unsigned char c : text) q.character(c);
    done_ += text.size();
  }

  void act(Viewer& viewer, InputQueue& q, GlfwWindow& window) {
    int w = 0, h = 0;
    glfwGetWindowSize(window.handle(), &w, &h);
    std::ostringstream what;
    const int choice = pick(100);
    if (choice < 22) {  // a click, mostly on a widget
      const auto [x, y] = somewhere(viewer, w, h, pick(4) != 0);
      if (onQuit(viewer, x, y)) return;
      const int button = pick(10) == 0 ? 1 : 0, times = pick(8) == 0 ? 2 : 1;
      click(q, x, y, button, times);
      what << "click " << button << " ×" << times << " at " << x << ", " << y;
    } else if (choice < 38) {  // a field typed into: Ctrl+click turns a drag field into a text field
      const auto [x, y] = somewhere(viewer, w, h, true);
      if (onQuit(viewer, x, y)) return;
      q.key(341, true);
      click(q, x, y);
      q.key(341, false);
      const std::string text = kTyped[size_t(pick(int(kTyped.size())))];
      type(q, text);
      const int end = pick(3);
      if (end == 0) press(q, keys::kEnter);
      else if (end == 1) press(q, 258);  // Tab: the next field
      else click(q, uniform(0, w), uniform(0, h));
      what << "typed \"" << text << "\" at " << x << ", " << y;
    } else if (choice < 52) {  // a drag: in a view (orbit, pan, a handle) or on a drag field
      auto [x, y] = somewhere(viewer, w, h, pick(3) != 0);
      if (onQuit(viewer, x, y)) return;
      const int button = pick(4) == 0 ? 1 : 0, steps = 2 + pick(6);
      q.mouseMove(x, y);
      q.mouseButton(button, true);
      for (int i = 0; i < steps; ++i) {
        x += uniform(-60, 60);
        y += uniform(-60, 60);
        q.mouseMove(x, y);
      }
      q.mouseButton(button, false);
      done_ += 3 + steps;
      what << "drag " << button << " to " << x << ", " << y;
    } else if (choice < 60) {  // the wheel
      const auto [x, y] = somewhere(viewer, w, h, pick(2) == 0);
      q.mouseMove(x, y);
      q.wheel(0, double(pick(7) - 3));
      done_ += 2;
      what << "wheel at " << x << ", " << y;
    } else if (choice < 82) {  // a key, now and then with Ctrl (undo, redo)
      const bool ctrl = pick(12) == 0;
      const int key = ctrl ? (pick(2) == 0 ? keys::kZ : keys::kY) : kKeys[size_t(pick(int(kKeys.size())))];
      if (!ctrl && key >= '0' && key <= '9') q.character(unsigned(key));  // a digit is a key and a character
      press(q, key, ctrl);
      what << "key " << key << (ctrl ? " with Ctrl" : "");
    } else if (choice < 87) {  // the window resized (a projector, a laptop, a narrow window)
      const int nw = 320 + pick(1600), nh = 240 + pick(960);
      glfwSetWindowSize(window.handle(), nw, nh);
      ++done_;
      what << "resize to " << nw << " × " << nh;
    } else if (choice < 93 && !lessons_.empty()) {  // a bundled lesson at a random step
      const fs::path& file = lessons_[size_t(pick(int(lessons_.size())))];
      const size_t step = size_t(pick(14));
      viewer.session().openLesson(file, step);
      ++done_;
      what << "lesson " << file.filename().string() << " step " << step + 1;
    } else if (choice < 96 && !scenes_.empty()) {  // a bundled scene (read on the loader's thread)
      const fs::path& file = scenes_[size_t(pick(int(scenes_.size())))];
      viewer.session().openScene(file);
      ++done_;
      what << "scene " << file.filename().string();
    } else if (choice < 98) {  // the UI scale of a projector
      const float scales[] = {1.f, 1.25f, 1.6f, 2.f};
      viewer.state().uiScale = scales[pick(4)];
      ++done_;
      what << "UI scale " << viewer.state().uiScale;
    } else {  // the other language
      Language& lang = viewer.state().display.language;
      lang = lang == Language::en ? Language::de : Language::en;
      ++done_;
      what << "language " << text::languageCode(lang);
    }
    lastAction_ = what.str();
  }

  std::mt19937 rng_;
  unsigned long events_, done_ = 0, frames_ = 0, windowFrames_ = 0, restarts_ = 0;
  std::vector<fs::path> lessons_, scenes_;
  double longest_ = 0;
  bool finished_ = false, quitInReach_ = false;
  std::string failure_, lastAction_ = "none", longestAfter_;
};

TEST(Monkey, TheWindowSurvivesRandomInputOverEveryLessonAndScene) {
  const unsigned seed = unsigned(envNumber("VPLAB_MONKEY_SEED", 37));
  const unsigned long events = envNumber("VPLAB_MONKEY_EVENTS", 3000);
  std::cout << "monkey: seed " << seed << ", " << events << " events" << std::endl;
  // The viewer's files (autosave, screenshots, exports) stay in a directory of the test's own.
  const fs::path work = fs::temp_directory_path() / ("vplab-monkey-" + std::to_string(::getpid()));
  fs::create_directories(work);
  fs::current_path(work);
  ::setenv("XDG_STATE_HOME", (work / "state").c_str(), 1);

  Monkey monkey(seed, events);
  ViewerLaunch launch;
  launch.scene = defaultScene();
  launch.width = 1024;  // a projector's 1024 × 768 less the title bar; resizes reach the rest
  launch.height = 600;
  launch.driver = [&monkey](Viewer& v, InputQueue& q, GlfwWindow& w, double last) { return monkey(v, q, w, last); };
  // A window ends with status 0 only when the user quit (every error ends it non-zero, issue 37): the
  // monkey's clicks can reach File ▸ Quit in a menu opened by the same batch of events, or the
  // unsaved-changes dialog's quit button. The user then starts the viewer again.
  constexpr unsigned long kMostRestarts = 100;
  int status = -1;
  for (;;) {
    try {
      status = runViewerWindow(launch);
    } catch (const std::exception& e) {
      FAIL() << "the window did not open: " << e.what();
    }
    if (status != 0 || monkey.finished() || !monkey.failure().empty() || monkey.restarts() >= kMostRestarts) break;
    if (!monkey.quitInReach()) {
      ADD_FAILURE() << "the viewer ended with status 0 while no menu or dialog was open (the last event: "
                    << monkey.lastAction() << ")";
      break;
    }
    std::cout << "monkey: the user quit after " << monkey.done() << " events (the last: " << monkey.lastAction()
              << "); starting the viewer again" << std::endl;
    monkey.restarted();
  }
  std::cout << "monkey: " << monkey.done() << " events in " << monkey.frames() << " frames, " << monkey.restarts()
            << " restarts after the user quit, the longest frame " << monkey.longest() << " s (after: "
            << monkey.longestAfter() << ")" << std::endl;
  const std::string replay = "replay: VPLAB_MONKEY_SEED=" + std::to_string(seed) +
                             " VPLAB_MONKEY_EVENTS=" + std::to_string(events) + " xvfb-run -a test_monkey";
  EXPECT_EQ(monkey.failure(), "") << replay;
  EXPECT_TRUE(monkey.finished() || !monkey.failure().empty())
      << "the viewer ended before the monkey was done (status " << status << ", the last event: " << monkey.lastAction()
      << ")\n" << replay;
  EXPECT_EQ(status, 0) << replay;
  fs::current_path(fs::temp_directory_path());
  std::error_code ec;
  fs::remove_all(work, ec);
}

}  // namespace
}  // namespace vplab
