// An exercise practised in the real window under Xvfb (issue 40), as a student does it: `vplab
// exercise` writes the folder, `vplab --exercise DIR` opens it, and the keyboard alone fills every
// field (the first takes the keys when the exercise opens; text, Tab, text, …; Ctrl+Enter checks).
// The pipeline sheet typed from its key earns full points; a divide-first answer to a clipping sheet
// is named, its polygon drawn in the NPC view where `vplab render --answer` draws it, and Hand in
// (File ▸ Hand in…, Enter in the dialog) writes the file `vplab grade batch` grades to the same points.
//
// Oracles: `vplab exercise`'s solution.json (the key) and the divide-first answer worked out here by
// a few lines of Sutherland–Hodgman on the divided polygon (Hill 7.4), never by the viewer.
#include "app/context/context_glfw.h"
#include "app/ui/input_queue.h"
#include "app/ui/keys.h"
#include "app/ui/run_viewer.h"
#include "app/ui/viewer.h"
#include "course/mistake_models.h"
#include "app/practice/practice.h"
#include "app/views/image.h"
#include "io/scene_io.h"
#include "tests/support/process.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <iostream>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr int kTab = 258, kEnter = 257, kLeftCtrl = 341;

Json readJson(const fs::path& file) {
  std::ifstream in(file);
  return Json::parse(in);
}

// ---------------------------------------------------------------- what the student types

/// A number as a student writes it: 6 decimals, the German decimal comma in every other one.
std::string onPaper(double x, size_t i) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", std::abs(x) < 5e-7 ? 0.0 : x);
  std::string t = buf;
  if (i % 2)
    if (const size_t dot = t.find('.'); dot != std::string::npos) t[dot] = ',';
  return t;
}

/// What is typed, field after field, for `answer` (the fields in the sheet's order, as the viewer has them).
std::vector<std::string> keystrokes(const std::vector<ItemFields>& fields, const Json& answer) {
  std::vector<std::string> out;
  for (const ItemFields& f : fields) {
    const Json& v = answer[Json::json_pointer(f.item.path)];
    switch (f.kind) {
      case FieldKind::number: out.push_back(onPaper(v.get<double>(), out.size())); break;
      case FieldKind::outcode: {
        std::string bits;
        for (int b = 5; b >= 0; --b) bits += (v.get<int>() >> b) & 1 ? '1' : '0';
        out.push_back(bits);
        break;
      }
      case FieldKind::vector:
        for (const Json& x : v) out.push_back(onPaper(x.get<double>(), out.size()));
        break;
      case FieldKind::polygon: out.push_back(std::to_string(v.size())); [[fallthrough]];
      case FieldKind::matrix:
        for (const Json& row : v)
          for (const Json& x : row) out.push_back(onPaper(x.get<double>(), out.size()));
        break;
    }
  }
  return out;
}

/// The divide-first answer of a clipping sheet: the polygon in homogeneous NPC divided by w first,
/// then clipped plane by plane (left x ≥ 0, right x ≤ w, bottom, top, back z ≥ 0, front z ≤ w; w = 1
/// now), each new vertex at t = BC(in) / (BC(in) − BC(out)); DC = (W x, H (1 − y), z).
Json divideFirstAnswer(const Json& npcH, const Json& dcFromNpc) {
  using V = std::array<double, 4>;
  auto boundary = [](const V& p, int k) {
    const double b[6] = {p[0], p[3] - p[0], p[1], p[3] - p[1], p[2], p[3] - p[2]};
    return b[k];
  };
  auto cut = [](const V& a, const V& b, double ba, double bb) {
    const double t = ba / (ba - bb);
    V v;
    for (int j = 0; j < 4; ++j) v[size_t(j)] = a[size_t(j)] + t * (b[size_t(j)] - a[size_t(j)]);
    return v;
  };
  std::vector<V> polygon;
  for (const Json& p : npcH) {
    const double w = p[3].get<double>();
    polygon.push_back({p[0].get<double>() / w, p[1].get<double>() / w, p[2].get<double>() / w, 1});
  }
  Json passes = Json::array();
  auto rows = [](const std::vector<V>& ps) {
    Json out = Json::array();
    for (const V& p : ps) out.push_back({p[0], p[1], p[2], p[3]});
    return out;
  };
  for (int k = 0; k < 6; ++k) {
    std::vector<V> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
      const V& s = polygon[(i + polygon.size() - 1) % polygon.size()];
      const V& e = polygon[i];
      const double bs = boundary(s, k), be = boundary(e, k);
      if (be >= 0) {
        if (bs < 0) out.push_back(cut(e, s, be, bs));
        out.push_back(e);
      } else if (bs >= 0) {
        out.push_back(cut(s, e, bs, be));
      }
    }
    polygon = out;
    passes.push_back({{"polygon", rows(polygon)}});
  }
  const double W = dcFromNpc[0][0].get<double>(), H = dcFromNpc[1][3].get<double>();
  Json dc = Json::array();
  for (const V& p : polygon) dc.push_back({W * p[0], H * (1 - p[1]), p[2]});
  Json answer;
  answer["objects"] = Json::array({{{"polygons", Json::array({{{"clip_steps", passes}, {"clipped_dc", dc}}})}}});
  answer["matrices"]["dc_from_npc"] = dcFromNpc;
  return answer;
}

// ---------------------------------------------------------------- the student at the keyboard

/// Plays the student (a ViewerDriver): waits for the Tasks, types `texts` with Tab after each (one
/// field a frame, as fast as a person never is), presses Ctrl+Enter, waits for Check; then, with
/// `handIn`, File ▸ Hand in… and Enter in the file dialog; then quits.
class Student {
 public:
  Student(std::vector<std::string> texts, bool handIn) : texts_(std::move(texts)), handIn_(handIn) {}

  bool operator()(Viewer& viewer, InputQueue& q, GlfwWindow&, double) {
    ++frames_;
    if (viewer.caught().count > 0) return fail("the viewer caught an error: " + viewer.caught().last);
    if (frames_ > 4000) return fail("the student never got to the end (step " + std::to_string(step_) + ")");
    if (q.pending() > 0) return true;
    const ViewerState& s = viewer.state();
    switch (step_) {
      case 0:  // the exercise open, its Tasks drawn, the first field holding the keys
        if (!s.practice || !ImGui::GetIO().WantTextInput || frames_ < 10) return true;
        fields_ = s.practice->fields;  // the sheet's order, for the test's keystrokes
        ++step_;
        return true;
      case 1:  // a field a frame: Tab, and when the next field has the keys, its text
        if (typed_ < texts_.size()) {
          if (typed_ > 0 && !tabbed_) {
            press(q, kTab);
            tabbed_ = true;
            return true;
          }
          for (unsigned char c : texts_[typed_]) q.character(c);
          ++typed_;
          tabbed_ = false;
          return true;
        }
        q.key(kLeftCtrl, true);
        press(q, kEnter);
        q.key(kLeftCtrl, false);
        ++step_;
        return true;
      case 2:
        if (!s.check || s.check->edits != s.practice->edits) return true;
        check_ = *s.check;
        practice_ = *s.practice;
        if (!handIn_) return done(viewer);
        click(q, viewer, "menu.file");
        ++step_;
        return true;
      case 3:
        if (!viewer.rects().rects.count("menu.handIn")) return true;
        click(q, viewer, "menu.handIn");
        ++step_;
        return true;
      case 4:  // the dialog's name field takes the keys as it opens: Enter saves what it suggests
        if (!ImGui::GetIO().WantTextInput || !viewer.rects().rects.count("dialog.fileName")) return true;
        press(q, kEnter);
        ++step_;
        return true;
      default:
        if (ImGui::GetIO().WantTextInput) return true;
        return done(viewer);
    }
  }

  const std::string& failure() const { return failure_; }
  const std::vector<ItemFields>& fieldsSeen() const { return fields_; }
  const std::optional<PracticeCheck>& check() const { return check_; }
  const std::optional<Practice>& practice() const { return practice_; }
  const ImVec4& npcView() const { return npcView_; }

 private:
  static void press(InputQueue& q, int key) {
    q.key(key, true);
    q.key(key, false);
  }
  static void click(InputQueue& q, const Viewer& viewer, const char* id) {
    const ImVec4& r = viewer.rects().rects.at(id);
    q.mouseMove(r.x + r.z / 2, r.y + r.w / 2);
    q.mouseButton(0, true);
    q.mouseButton(0, false);
  }
  bool done(const Viewer& viewer) {
    npcView_ = viewer.rects().rects.at("view.npc");
    finished_ = true;
    return false;
  }
  bool fail(std::string why) {
    failure_ = std::move(why);
    return false;
  }

  std::vector<std::string> texts_;
  bool handIn_;
  int step_ = 0;
  size_t typed_ = 0;
  bool tabbed_ = false;
  unsigned long frames_ = 0;
  bool finished_ = false;
  std::vector<ItemFields> fields_;
  std::optional<PracticeCheck> check_;
  std::optional<Practice> practice_;
  ImVec4 npcView_{};
  std::string failure_;
};

class PracticeWindow : public test::ProcessTest {
 protected:
  void SetUp() override {
    ProcessTest::SetUp();
    ::setenv("XDG_STATE_HOME", (dir_ / "state").c_str(), 1);  // the kept answers: the test's own
    ::setenv("XDG_CONFIG_HOME", (dir_ / "config").c_str(), 1);
  }

  /// Runs `vplab ARGS` (the binary the build made; ARGS' paths quoted by the caller) and returns its
  /// standard output; a non-zero status fails the test.
  std::string vplab(const std::string& args) {
    const test::ProcessResult r = sh(test::shellQuoted(VPLAB_EXE) + " " + args);
    EXPECT_EQ(r.exitCode, 0) << "vplab " << args << "\n" << r.err;
    return r.out;
  }

  /// The viewer on `folder` driven by `student`; the window's picture at the end in `shot`.
  void run(const fs::path& folder, Student& student, const fs::path& shot) {
    ViewerLaunch launch;
    launch.scene = loadScene(folder / "scene.json");
    launch.exercise = folder.string();
    launch.width = 1280;  // the Xvfb screen is 1280 × 800: the tall column on the left holds the Tasks
    launch.height = 800;
    launch.language = Language::en;
    launch.screenshotOnQuit = shot.string();
    launch.driver = [&student](Viewer& v, InputQueue& q, GlfwWindow& w, double last) { return student(v, q, w, last); };
    EXPECT_EQ(runViewerWindow(launch), 0);
    ASSERT_EQ(student.failure(), "");
  }
};

/// What was typed is what the fields hold, field after field.
std::vector<std::string> textsOf(const std::vector<ItemFields>& fields) {
  std::vector<std::string> out;
  for (const ItemFields& f : fields) {
    if (f.kind == FieldKind::polygon) out.push_back(std::to_string(f.rows));
    out.insert(out.end(), f.texts.begin(), f.texts.end());
  }
  return out;
}

TEST_F(PracticeWindow, EveryFieldOfThePipelineSheetTypedFromTheKeyboardEarnsFullPoints) {
  const fs::path folder = dir_ / "pipeline";
  vplab("exercise --seed 4 --topic pipeline --student-id 100 --out " + test::shellQuoted(folder));
  const Json key = readJson(folder / "solution.json");
  // The fields' order is the sheet's (as the viewer lays it out), the values the key's.
  const std::vector<std::string> texts = keystrokes(openPracticeFolder(folder, Reveal::stages, Language::en).fields, key);
  ASSERT_GT(texts.size(), 60u) << "the pipeline sheet has its matrices, vectors and outcode";
  Student student(texts, false);
  run(folder, student, dir_ / "pipeline.png");
  ASSERT_TRUE(student.check());
  EXPECT_EQ(textsOf(student.practice()->fields), texts) << "every field holds what was typed into it, in the sheet's order";
  const PracticeCheck& check = *student.check();
  std::string failed;
  for (const GradeCase& c : check.report.cases)
    if (!c.passed) failed += "\n" + c.name + ": " + c.message;
  EXPECT_EQ(check.report.points, check.report.maxPoints) << failed;
  EXPECT_TRUE(check.report.passed);
  std::cout << "the pipeline sheet: " << texts.size() << " fields typed; Check took " << check.seconds * 1000 << " ms" << std::endl;
}

/// The student's colour in the dark theme (255 89 217) and its antialiased edges; not VUP's violet.
std::vector<uint8_t> studentMask(const Image& png, int x0, int y0, int w, int h) {
  std::vector<uint8_t> mask(size_t(w) * size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgba& c = png.pixels[size_t(y0 + y) * size_t(png.width) + size_t(x0 + x)];
      mask[size_t(y) * size_t(w) + size_t(x)] = c.r > 150 && c.b > 0.6 * c.r && c.b < 0.95 * c.r && c.g < 0.42 * c.r;
    }
  return mask;
}

TEST_F(PracticeWindow, ADivideFirstAnswerIsNamedDrawnWhereTheRenderDrawsItAndHandedInAsGradeBatchGradesIt) {
  const fs::path folder = dir_ / "clipping";
  vplab("exercise --seed 3 --topic clipping --out " + test::shellQuoted(folder));
  const Json dump = Json::parse(vplab("dump --scene " + test::shellQuoted(folder / "scene.json")));
  const Json key = readJson(folder / "solution.json");
  const Json answer = divideFirstAnswer(dump["objects"][0]["polygons"][0]["npc_h"], key["matrices"]["dc_from_npc"]);
  Student student(keystrokes(openPracticeFolder(folder, Reveal::stages, Language::en).fields, answer), true);
  const fs::path shot = dir_ / "clipping.png";
  run(folder, student, shot);
  ASSERT_TRUE(student.check());
  const PracticeCheck& check = *student.check();
  ASSERT_TRUE(check.grade.mistake);
  EXPECT_EQ(*check.grade.mistake, Mistake::divideFirst) << check.report.diagnosis.size();
  EXPECT_LT(check.report.points, check.report.maxPoints);

  // Hand in wrote the answer where the dialog suggested it (the exercise's folder), naming its exercise.
  const Json handedIn = readJson(folder / "answer.json");
  EXPECT_EQ(handedIn["exercise"]["seed"], 3);
  EXPECT_GE(handedIn["objects"][0]["polygons"][0]["clip_steps"][5]["polygon"].size(), 3u);
  fs::create_directories(dir_ / "answers");
  fs::copy_file(folder / "answer.json", dir_ / "answers" / "s100.json");
  vplab("grade batch --assignment " + test::shellQuoted(folder / "assignment.json") + " --answers " +
        test::shellQuoted(dir_ / "answers") + " --out " + test::shellQuoted(dir_ / "grades"));
  const Json results = readJson(dir_ / "grades" / "results.json");
  ASSERT_EQ(results["students"].size(), 1u);
  EXPECT_EQ(results["students"][0]["id"], "s100");
  EXPECT_DOUBLE_EQ(results["students"][0]["score"].get<double>(), check.report.points)
      << "vplab grade batch gives the handed-in answer the points Check gave";

  // The NPC view shows their polygon dashed where `vplab render --answer` draws it.
  const ImVec4 r = student.npcView();
  const int x = int(std::lround(r.x)), y = int(std::lround(r.y)), w = int(std::lround(r.z)), h = int(std::lround(r.w));
  const fs::path expectedFile = dir_ / "npc-divide-first.png";
  vplab("render --view npc --style shaded --exercise " + test::shellQuoted(folder) + " --answer " +
        test::shellQuoted(folder / "answer.json") + " --size " + std::to_string(w) + "x" + std::to_string(h) +
        " --out " + test::shellQuoted(expectedFile));
  const Image window = readPng(shot), expected = readPng(expectedFile);
  ASSERT_GE(window.width, x + w);
  ASSERT_GE(window.height, y + h);
  const std::vector<uint8_t> shown = studentMask(window, x, y, w, h), rendered = studentMask(expected, 0, 0, w, h);
  size_t both = 0, inShown = 0, inRendered = 0;
  for (size_t i = 0; i < shown.size(); ++i) {
    both += shown[i] & rendered[i];
    inShown += shown[i];
    inRendered += rendered[i];
  }
  // Every pixel of their colour the window shows is one the render has (5 %: antialiasing and the
  // labels), and most of the render's are shown: the window draws the lab's step-through over parts.
  EXPECT_GT(inRendered, 150u) << "the rendered outline is visible";
  EXPECT_GE(double(both), 0.95 * double(inShown)) << "shown " << inShown << ", rendered " << inRendered << ", both " << both;
  EXPECT_GT(double(both), 0.5 * double(inRendered)) << "shown " << inShown << ", rendered " << inRendered << ", both " << both;
}

}  // namespace
}  // namespace vplab
