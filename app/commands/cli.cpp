#include "app/commands/cli.h"

#include "app/document/assets.h"
#include "app/lessons/lesson.h"
#include "app/practice/practice.h"
#include "app/practice/practice_marks.h"
#include "app/lessons/tabs.h"
#include "app/document/preferences.h"
#include "app/text/catalogue.h"
#include "app/export/progress_bar.h"
#include "app/commands/lesson_export.h"
#include "app/commands/bench_command.h"
#include "app/commands/course_commands.h"
#include "app/commands/number_argument.h"
#include "app/export/svg.h"
#include "app/render/headless.h"
#include "app/ui/headless_viewer.h"
#include "app/ui/run_viewer.h"
#include "io/dump.h"
#include "base/error.h"
#include "io/limits.h"
#include "io/read_file.h"
#include "io/scene_io.h"

#include <CLI/CLI.hpp>
#include <vplab_version.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace vplab {

namespace {

Scene sceneFrom(const std::string& path) { return path.empty() ? defaultScene() : loadScene(path); }

// ---------------------------------------------------------------- option checks

/// A finite number from lo to hi (CLI11's Range lets NaN through: every comparison with it is false).
/// CLI::IsMember over every value of an enum, by its name (the enum's one table and toString), and
/// any further names.
template <typename Enum, size_t N>
CLI::IsMember choicesOf(const std::array<Enum, N>& all, std::vector<std::string> more = {}) {
  std::vector<std::string> names;
  for (Enum e : all) names.emplace_back(toString(e));
  names.insert(names.end(), more.begin(), more.end());
  return CLI::IsMember(names);
}

CLI::Validator finiteIn(double lo, double hi) {
  std::ostringstream range;
  range << "a finite number from " << lo << " to " << hi;
  return CLI::Validator(
      [lo, hi, expected = range.str()](std::string& s) -> std::string {
        if (!numberArgument(s, lo, hi)) return "\"" + s + "\" is not " + expected;
        return {};
      },
      "FLOAT in [" + CLI::detail::to_string(lo) + " - " + CLI::detail::to_string(hi) + "]");
}

/// Output files by extension: what vplab can write, and nothing it would write in another format.
/// Why `file` is not one of the `extensions` vplab writes there (empty: it is).
std::string extensionError(const std::string& file, const std::vector<std::string>& extensions) {
  std::string list;
  for (const auto& e : extensions) list += (list.empty() ? "" : " or ") + e;
  std::string ext = std::filesystem::path(file).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& e : extensions)
    if (ext == e) return {};
  return "\"" + file + "\": vplab writes only " + list + " files" +
         (ext.empty() ? std::string(", and this name has no extension") : ", not " + ext);
}

CLI::Validator extensionIn(std::vector<std::string> extensions) {
  std::string list;
  for (const auto& e : extensions) list += (list.empty() ? "" : " or ") + e;
  return CLI::Validator([extensions](std::string& s) { return extensionError(s, extensions); }, list);
}

/// What `render --out` must be: a directory for a lesson's stills, a .gif for an animation, else a
/// .png or .svg picture. A usage error (exit 2) names what is wrong, as the parser's checks do.
std::string renderOutError(const std::string& out, bool lesson, bool animate) {
  if (animate) return out.empty() ? "--animate needs --out FILE.gif" : extensionError(out, {".gif"});
  if (lesson) return out.empty() ? "--lesson needs --out DIR: the directory for its pictures and index.md" : "";
  return out.empty() ? "" : extensionError(out, {".png", ".svg"});
}

/// The picture `vplab render` makes must stay within the image limits (io/limits.h), checked
/// before any framebuffer is made. --view all puts three views side by side under a title strip.
void checkImageSize(const std::string& view, int w, int h) {
  const bool all = view == "all";
  const int64_t width = all ? 3 * int64_t(w) + 12 : w, height = all ? int64_t(h) + 64 : h;  // 64: the titles, at most
  const std::string what = all ? "--view all puts three " + std::to_string(w) + " × " + std::to_string(h) +
                                     " views side by side: about " + std::to_string(width) + " × " +
                                     std::to_string(height) + " pixels, which"
                               : "the picture of " + std::to_string(w) + " × " + std::to_string(h) + " pixels";
  if (width > kMaxImageSide || height > kMaxImageSide)
    throw Error(what + " exceeds the limit of " + std::to_string(kMaxImageSide) + " pixels per side" +
                (all ? "; each view may be at most " + std::to_string((kMaxImageSide - 12) / 3) + " × " +
                           std::to_string(kMaxImageSide - 64)
                     : std::string()));
  if (width * height > kMaxImagePixels)
    throw Error(what + " exceeds the limit of " + std::to_string(kMaxImagePixels) + " pixels in one picture");
}

struct DumpOptions {
  std::string scene;
  std::string strategy = "npc";
  bool boundingBox = false;
  int indent = 2;
};

int runDump(const DumpOptions& d) {
  PipelineOptions options;
  options.strategy = *fromString<ClipStrategy>(d.strategy);
  options.boundingBoxTest = d.boundingBox;
  const PipelineRun run = runPipeline(sceneFrom(d.scene), options);
  try {
    // Streamed: the text of a large scene never exists in memory as a whole. A reader that goes
    // away (`vplab dump | head`) is a write error, not a SIGPIPE.
    std::signal(SIGPIPE, SIG_IGN);
    std::ios::sync_with_stdio(false);
    writeDump(std::cout, run, d.indent);
  } catch (const Error& e) {
    throw Error((d.scene.empty() ? std::string("the default scene") : d.scene) + ": " + e.what());
  }
  return 0;
}

struct RenderOptions {
  std::string scene;
  std::string view = "camera";
  std::string style = "flat";
  std::string size;
  std::string out;
  std::string backend = "auto";
  std::string strategy = "npc";
  std::string theme = "dark";
  float uiScale = 1.f;
  std::string lang = "en";        // the labels' (and with --view ui the panels') language
  double morphT = 0;
  bool glDebug = false;
  bool styleGiven = false;
  std::vector<std::string> tabs;  // --view ui: the panels' tabs to show
  std::string lesson;             // a lesson's steps (docs/lecturers.md "Lessons"), into the directory --out
  std::string format = "png";     // of a lesson's stills
  bool animate = false;           // a lesson's moves or the stage morph as an animated GIF
  int fps = 15;
  double hold = 3;                // seconds each step's still (each stage of the morph) is shown
  bool viewGiven = false;
  std::string exercise;           // an exercise's folder: its scene, and with --answer the student's numbers drawn
  std::string answer;             // a student's answer.json to the exercise
};

/// `render --exercise DIR [--answer FILE]`: the exercise with the answer's values in its fields.
std::optional<Practice> renderedPractice(const RenderOptions& r) {
  if (r.exercise.empty()) return std::nullopt;
  Practice p = openPracticeFolder(r.exercise, Reveal::stages, r.lang == "de" ? Language::de : Language::en);
  if (!r.answer.empty()) {
    for (ItemFields& f : p.fields) std::fill(f.texts.begin(), f.texts.end(), std::string());
    fillFields(p.fields, parseAnswer(readRegularFile(r.answer, kDefaultLimits.sceneFileBytes, "answer"), r.answer));
    ++p.edits;
  }
  return p;
}

/// ".png" of "Shot.PNG": what --out's name says it is.
std::string lowerExtension(const std::string& file) {
  std::string extension = std::filesystem::path(file).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

std::pair<int, int> parseSize(const std::string& s) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 1 || h < 1 ||
      w > 16384 || h > 16384)
    throw Error("--size \"" + s + "\" is not WIDTHxHEIGHT with 1 to 16384 pixels each, for example 1280x720");
  return {w, h};
}

/// A lesson given on the command line: a file, or a bundled lesson's name ("02-view-orientation",
/// in English unless ".de" follows).
/// How many single-character edits (insert, delete, replace) turn `a` into `b` (Levenshtein).
size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The bundled lesson's name nearest to a misspelt one ("05-cliping.de" → "05-clipping.de"), written as
/// it was (with or without its language), or empty when none is near.
std::string nearestLessonName(const std::string& given) {
  const bool withLanguage = given.ends_with(".de") || given.ends_with(".en");
  std::string best;
  size_t bestDistance = std::max<size_t>(2, given.size() / 4) + 1;
  for (Language lang : {Language::en, Language::de})
    for (const LessonFileInfo& l : listBundledLessons(lang)) {
      std::string name = l.file.stem().string();  // "05-clipping.de"
      if (!withLanguage) name = name.substr(0, name.find('.'));
      if (const size_t d = editDistance(given, name); d < bestDistance) {
        bestDistance = d;
        best = name;
      }
    }
  return best;
}

/// A lesson given on the command line: a file, else a bundled lesson by its name, in `language`
/// (the UI's) when the name does not say ".de" or ".en". A name that is neither says so in that
/// language and offers the nearest bundled one.
std::filesystem::path lessonFileFrom(const std::string& given, Language language) {
  std::error_code ec;
  if (std::filesystem::exists(given, ec)) return given;
  const std::filesystem::path bundled = bundledLessonFile(given, language);
  if (!bundled.empty()) return bundled;
  if (const std::string near = nearestLessonName(given); !near.empty())
    throw Error(text::fill(language, "--lesson {1}: no such file and no bundled lesson of that name; did you mean {2}? (`vplab lessons` lists them)",
                           {given, near}));
  throw Error(text::fill(language, "--lesson {1}: no such file and no bundled lesson of that name (`vplab lessons` lists them)", {given}));
}

/// `render --lesson`: every step as a still and the index, or with --animate the lesson as a GIF.
int renderLesson(const RenderOptions& r) {
  const std::filesystem::path file = lessonFileFrom(r.lesson, r.lang == "de" ? Language::de : Language::en);
  LessonContext lessonContext;
  lessonContext.scenesDirectory = assetsDirectory() / "scenes";
  const Lesson lesson = loadLesson(file, lessonContext);
  LessonPictureOptions o;
  o.view = r.viewGiven ? *fromString<ViewKind>(r.view) : ViewKind::all;
  o.theme = *fromString<Theme>(r.theme);
  o.scale = r.uiScale;
  if (!r.size.empty()) std::tie(o.width, o.height) = parseSize(r.size);

  StopRequests stop;
  ProgressBar bar("vplab render --lesson", r.animate ? "frames" : "pictures");
  const LessonProgress progress = [&](size_t done, size_t total) {
    bar(done, total);
    return !stop.requested();
  };
  std::unique_ptr<GlContext> context;
  std::optional<ViewRenderer> renderer;
  if (r.animate || r.format == "png") {
    context = createHeadlessContext(*fromString<Backend>(r.backend), r.glDebug);
    renderer.emplace(*context, o.scale);
  }
  if (r.animate) {
    AnimationOptions a;
    a.fps = r.fps;
    a.holdSeconds = r.hold;
    writeLessonAnimation(*renderer, lesson, o, a, r.out, progress);
  } else {
    writeLessonStills(renderer ? &*renderer : nullptr, lesson, o, r.format == "svg", r.out, progress);
  }
  if (stop.requested()) throw Error("stopped (Ctrl+C)" + std::string(r.animate ? ": no animation was written" : ": the pictures so far are kept"));
  return 0;
}

int runRender(const RenderOptions& r) {
  if (!r.lesson.empty()) return renderLesson(r);
  const std::optional<Practice> practice = renderedPractice(r);
  const Scene scene = practice ? practice->exercise.scene : sceneFrom(r.scene);
  if (r.animate) {
    if (r.view != "morph") throw Error("--animate is for --lesson or --view morph");
    RenderRequest request;
    request.view = ViewKind::morph;
    request.style = *fromString<Style>(r.style);
    request.theme = *fromString<Theme>(r.theme);
    if (!r.size.empty()) std::tie(request.width, request.height) = parseSize(r.size);
    const PixelSize size = pixelSizeOf(request, scene);
    checkImageSize(r.view, size.width, size.height);
    auto context = createHeadlessContext(*fromString<Backend>(r.backend), r.glDebug);
    ViewRenderer renderer(*context, r.uiScale);
    StopRequests stop;
    ProgressBar bar("vplab render --animate", "frames");
    AnimationOptions a;
    a.fps = r.fps;
    a.holdSeconds = r.hold;
    writeMorphAnimation(renderer, scene, displaySettingsOf(request, scene), size.width, size.height, a, r.out,
                        [&](size_t done, size_t total) {
                          bar(done, total);
                          return !stop.requested();
                        });
    if (stop.requested()) throw Error("stopped (Ctrl+C): no animation was written");
    return 0;
  }

  // The picture asked for, as the viewer's export and the tests describe one (app/views/render_request.h).
  RenderRequest request;
  if (r.view != "ui") request.view = *fromString<ViewKind>(r.view);
  request.style = *fromString<Style>(r.style);
  request.pipeline.strategy = *fromString<ClipStrategy>(r.strategy);
  request.morphT = r.morphT;
  request.theme = *fromString<Theme>(r.theme);
  request.scale = r.uiScale;
  request.language = r.lang == "de" ? Language::de : Language::en;
  if (!r.size.empty()) std::tie(request.width, request.height) = parseSize(r.size);
  if (practice) request.highlights.student = practiceMarks(*practice, std::nullopt);
  // Non-finite results are an error here as in the dump (coordinates so large that a product
  // overflows), said before the views derive their observers from them.
  if (auto e = nonFiniteError(runPipeline(scene, pipelineOptionsOf(request))))
    throw Error((r.scene.empty() ? std::string("the default scene") : r.scene) + ": " + *e);
  if (r.view == "ui") {
    checkImageSize(r.view, request.width > 0 ? request.width : 1280, request.height > 0 ? request.height : 720);
  } else {
    const PixelSize size = pixelSizeOf(request, scene);
    checkImageSize(r.view, size.width, size.height);
  }
  const std::string out = r.out.empty() ? "vplab-" + r.view + ".png" : r.out;
  const std::string extension = lowerExtension(out);
  if (extension == ".svg") {
    // The same picture as the PNG of the same request, as vector graphics for slides and lecture
    // notes: drawn by the SVG backend on the CPU, no GL context needed.
    if (r.view == "ui") throw Error("--view ui has no SVG form: write a PNG");
    writeSvg(svgOfRequest(scene, request), out);
    return 0;
  }
#ifndef NDEBUG
  const bool debug = true;  // debug builds treat every GL error as a failure
#else
  const bool debug = r.glDebug;
#endif
  auto context = createHeadlessContext(*fromString<Backend>(r.backend), debug);
  if (r.view == "ui") {
    // The whole window, panels included, as `vplab` shows it (1280 × 720 unless --size says).
    HeadlessViewer viewer(*context, scene, request.width > 0 ? request.width : 1280,
                          request.height > 0 ? request.height : 720, request.scale);
    // What the viewer shows for the same options (its keys 1 … 5 and C set the same).
    viewer.state().pipeline.strategy = request.pipeline.strategy;
    if (r.styleGiven) {
      DisplaySettings& d = viewer.state().display;
      d.camera.style = d.world.style = d.npc.style = request.style;
    }
    viewer.state().display.theme = request.theme;
    viewer.state().display.language = request.language;
    for (const std::string& tab : r.tabs) selectTab(viewer.state(), tab);
    if (practice) {
      // The exercise as the student left it, checked: its Tasks beside the views.
      viewer.frames(2);
      if (!viewer.viewer().session().exercises().openFolder(r.exercise, practice->reveal)) throw Error(viewer.state().status);
      viewer.state().practice->fields = practice->fields;
      ++viewer.state().practice->edits;
      if (!r.answer.empty()) viewer.viewer().session().exercises().check();
      for (int i = 0; i < 600 && !viewer.viewer().viewsNotReady().empty(); ++i) viewer.frame();
    }
    viewer.frames(3);
    writePng(viewer.image(), out);
    return 0;
  }
  ViewRenderer renderer(*context, request.scale);
  writePng(renderImage(renderer, scene, request), out);
  return 0;
}

struct ViewerOptions {
  std::string scene;
  std::string lesson;
  size_t step = 1;  // from 1, as the caption box counts
  int quitAfterFrames = 0;
  std::string screenshot;
  double waitForViews = ViewerLaunch{}.waitForViews;  // the window's own default (app/ui/run_viewer.h)
  float uiScale = 1.f;
  std::string lang;  // --lang en|de; empty: the remembered choice, else the locale's
  bool glDebug = false;
  bool reportFrames = false;
  std::string noDisplayDir;  // --no-display-dir: where the fallback writes; empty: it writes nothing
  std::string exercise;      // --exercise DIR: an exercise's folder to practise
  std::string reveal = "stages";
};

// The window could not be opened at start (no display, no OpenGL): say so, and only when asked
// (--no-display-dir) leave what can be made headless instead. Nothing is written into the working
// directory unasked (issue 37).
int viewerFallback(const ViewerOptions& v, const std::string& why) {
  std::cerr << "vplab: " << why << "\n";
  if (v.noDisplayDir.empty()) {
    std::cerr << "vplab: --no-display-dir DIR writes the scene's pipeline dump and its three views there instead; "
                 "`vplab render` and `vplab dump` make pictures and dumps without a display\n";
    return 1;
  }
  const std::filesystem::path dir = v.noDisplayDir;
  const std::filesystem::path dumpFile = dir / "vplab-dump.json", allFile = dir / "vplab-all.png";
  std::cerr << "vplab: writing the pipeline dump to " << dumpFile.string() << " and the three views to "
            << allFile.string() << " instead\n";
  const Scene scene = sceneFrom(v.scene);
  {
    std::ofstream out(dumpFile);
    out << dumpJson(runPipeline(scene, {}));
    if (!out) throw Error(dumpFile.string() + ": cannot write the dump");
  }
  try {
    auto context = createHeadlessContext(Backend::automatic, false);
    RenderRequest request;
    request.view = ViewKind::all;
    request.style = Style::shaded;
    request.scale = v.uiScale;
    ViewRenderer renderer(*context, request.scale);
    writePng(renderImage(renderer, scene, request), allFile);
  } catch (const Error& e) {
    std::cerr << "vplab: no headless picture either: " << e.what() << "\n";
  }
  return 0;
}

int runViewer(const ViewerOptions& v) {
  ViewerLaunch launch;
  launch.scene = sceneFrom(v.scene);
  if (!v.lesson.empty()) {
    // Read here first, so that a broken lesson ends with its error before a window opens.
    LessonContext context;
    context.scenesDirectory = assetsDirectory() / "scenes";
    // The lesson in the language the window will speak: --lang, else the remembered one, else the locale's.
    const Language language =
        startLanguage(v.lang.empty() ? std::nullopt : std::optional(v.lang == "de" ? Language::de : Language::en),
                      readPreferences(defaultPreferencesFile(), nullptr));
    const std::filesystem::path file = lessonFileFrom(v.lesson, language);
    const Lesson lesson = loadLesson(file, context);
    if (v.step > lesson.steps.size())
      throw Error("--step " + std::to_string(v.step) + ": the lesson " + v.lesson + " has " +
                  std::to_string(lesson.steps.size()) + " steps");
    launch.lesson = file.string();
    launch.lessonStep = v.step - 1;
  }
  if (!v.exercise.empty()) {
    const std::optional<Reveal> reveal = fromString<Reveal>(v.reveal);
    if (!reveal) throw Error("--reveal \"" + v.reveal + "\": values, stages or none expected");
    // Read here first, so that a folder that is no exercise ends with its error before a window opens.
    launch.scene = openPracticeFolder(v.exercise, *reveal, Language::en).exercise.scene;
    launch.exercise = v.exercise;
    launch.reveal = *reveal;
  }
  launch.quitAfterFrames = v.quitAfterFrames;
  launch.screenshotOnQuit = v.screenshot;
  launch.waitForViews = v.waitForViews;
  launch.uiScale = v.uiScale;
  if (!v.lang.empty()) launch.language = v.lang == "de" ? Language::de : Language::en;
  launch.reportFrames = v.reportFrames;
#ifndef NDEBUG
  launch.glDebug = true;
#else
  launch.glDebug = v.glDebug;
#endif
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    return viewerFallback(v, "no display (DISPLAY is not set): the interactive viewer needs one");
  try {
    return runViewerWindow(std::move(launch));  // past the window's opening it returns, never throws
  } catch (const Error& e) {
    return viewerFallback(v, e.what());
  }
}

}  // namespace

namespace {

/// `vplab presets`: name, title and file of each bundled scene, one per line.
int runPresets() {
  const std::vector<SceneFileInfo> presets = listPresetScenes();
  if (presets.empty())
    throw Error("no bundled scenes found: an installed vplab reads them from share/vplab/scenes beside its bin/ "
                "directory (cmake --install), a built one from the source tree's assets/scenes");
  for (const SceneFileInfo& p : presets) {
    const std::string name = p.file.stem().string();
    std::cout << name << std::string(name.size() < 26 ? 26 - name.size() : 1, ' ') << p.title << "\n    "
              << p.file.string() << "\n";
  }
  return 0;
}

/// `vplab lessons`: name, title and file of each bundled lesson, English then German.
int runLessons() {
  bool any = false;
  for (const Language language : {Language::en, Language::de})
    for (const LessonFileInfo& l : listBundledLessons(language)) {
      const std::string name = l.file.filename().string().substr(0, l.file.filename().string().size() - 5);  // without .json
      std::cout << name << std::string(name.size() < 30 ? 30 - name.size() : 1, ' ') << l.title << "\n    " << l.file.string() << "\n";
      any = true;
    }
  if (!any)
    throw Error("no bundled lessons found: an installed vplab reads them from share/vplab/lessons beside its bin/ "
                "directory (cmake --install), a built one from the source tree's assets/lessons");
  return 0;
}

}  // namespace

int runCommandLine(int argc, char** argv) {
  CLI::App app{"vplab — Viewing Pipeline Lab: the 3D viewing pipeline (modeling, view orientation, "
               "view mapping, clipping in homogeneous coordinates, device mapping), step by step.\n"
               "Without a subcommand, opens the interactive viewer."};
  app.set_version_flag("--version", "vplab " VPLAB_VERSION " (git " VPLAB_COMMIT ")");

  ViewerOptions viewer;
  CLI::Option* sceneOption =
      app.add_option("--scene", viewer.scene, "Scene file (JSON) to open; default: the built-in lecture scene")
          ->check(CLI::ExistingFile);
  // A file manager and the desktop entry (packaging/vplab.desktop) open a scene by its name alone.
  CLI::Option* fileOption = app.add_option("file", viewer.scene, "A scene file to open, as --scene FILE")
                                ->check(CLI::ExistingFile)
                                ->excludes(sceneOption);
  CLI::Option* lessonOption =
      app.add_option("--lesson", viewer.lesson, "A lesson to present (docs/lecturers.md \"Lessons\"): a file, or a "
                                                "bundled one by its name (`vplab lessons` lists them); its steps with "
                                                "captions, advanced with → / Space / Page Down")
          ->excludes(sceneOption)
          ->excludes(fileOption);
  app.add_option("--step", viewer.step, "The lesson's step to open, from 1 (default 1)")
      ->check(CLI::Range(1, 100000))
      ->needs(lessonOption);
  CLI::Option* exerciseOption =
      app.add_option("--exercise", viewer.exercise,
                     "An exercise's folder (written by `vplab exercise --out DIR`) to practise: its tasks beside the "
                     "views, the student's numbers checked and drawn in them (docs/students.md \"Practising\")")
          ->check(CLI::ExistingDirectory)
          ->excludes(sceneOption)
          ->excludes(fileOption)
          ->excludes(lessonOption);
  app.add_option("--reveal", viewer.reveal,
                 "With --exercise: what Check shows of the reference: stages (default: which values are wrong, the "
                 "first departing stage and the mistake named), values (the reference values too) or none")
      ->needs(exerciseOption);
  app.add_option("--quit-after-frames", viewer.quitAfterFrames,
                 "Quit by itself after N frames (for smoke tests and scripted screenshots)")
      ->check(CLI::Range(1, 100000000));
  app.add_option("--screenshot", viewer.screenshot, "Write a PNG of the whole window when quitting")
      ->check(extensionIn({".png"}));
  app.add_option("--wait-for-views", viewer.waitForViews,
                 "Seconds that --screenshot, F12 and --quit-after-frames wait for every shown view's current "
                 "image (never an \"updating…\" frame); past them --quit-after-frames fails (status 1) naming "
                 "the views (default 30)")
      ->check(finiteIn(0, 3600));
  app.add_option("--ui-scale", viewer.uiScale, "Scale fonts and handles (1.5 or 2 for a projector)")
      ->check(finiteIn(0.5, 4));
  app.add_option("--lang", viewer.lang,
                 "The language of the menus, panels and views' labels: en or de (default: the one last chosen "
                 "in View > Language, else the locale's)")
      ->check(CLI::IsMember({"en", "de"}));
  app.add_flag("--gl-debug", viewer.glDebug, "Turn on KHR_debug and fail on any OpenGL error");
  app.add_flag("--report-frames", viewer.reportFrames, "Print how many frames the window drew when it ends (tests)");
  app.add_option("--no-display-dir", viewer.noDisplayDir,
                 "When no window can be opened (no display): write the scene's pipeline dump (vplab-dump.json) "
                 "and its three views (vplab-all.png) into this directory instead, and end with status 0 "
                 "(without it: status 1, nothing written)")
      ->check(CLI::ExistingDirectory);

  DumpOptions dump;
  CLI::App* dumpCmd = app.add_subcommand("dump", "Run the CPU pipeline and print every stage's results as JSON");
  dumpCmd->add_option("--scene", dump.scene, "Scene file (JSON); default: the built-in lecture scene")
      ->check(CLI::ExistingFile);
  dumpCmd->add_option("--strategy", dump.strategy,
                      "Clipping strategy: npc (homogeneous NPC, the default), wc (the six frustum "
                      "planes in WC) or divide-first (wrong on purpose: divides by w before clipping)")
      ->check(choicesOf(allOf<ClipStrategy>()));
  dumpCmd->add_flag("--bounding-box", dump.boundingBox,
                    "Decide whole objects by their bounding box first (lecture notes 15.3.4)");
  dumpCmd->add_option("--indent", dump.indent, "JSON indentation; -1 prints everything on one line")
      ->check(CLI::Range(-1, 8));

  RenderOptions render;
  CLI::App* renderCmd = app.add_subcommand("render", "Render a view headless (EGL or OSMesa) to a PNG file");
  CLI::Option* renderScene = renderCmd->add_option("--scene", render.scene, "Scene file (JSON); default: the built-in lecture scene")
      ->check(CLI::ExistingFile);
  CLI::Option* renderExercise =
      renderCmd->add_option("--exercise", render.exercise,
                            "An exercise's folder (vplab exercise --out DIR): its scene; with --view ui its Tasks beside the views")
          ->check(CLI::ExistingDirectory)
          ->excludes(renderScene);
  renderCmd->add_option("--answer", render.answer,
                        "With --exercise: a student's answer.json, its numbers drawn in the views in the student's colour "
                        "(and with --view ui typed into the Tasks and checked)")
      ->check(CLI::ExistingFile)
      ->needs(renderExercise);
  renderCmd->add_option("--view", render.view,
                        "camera (what the synthetic camera sees, W × H, pixel-aligned with DC), world (an "
                        "observer's view of scene, camera and view volume), npc (the unit cube after view "
                        "mapping, clipping and division), all (the three side by side), morph (the stage "
                        "morph at --morph-t), divide-first (what dividing by w before clipping draws, the "
                        "Clipping lesson's wrong picture; always the divide-first strategy's run), depth-plot "
                        "(NPC z and GL window depth against VRC z, the objects' depth ranges) or ui (the whole "
                        "viewer window with its panels; needs EGL)")
      ->check(choicesOf(allOf<ViewKind>(), {"ui"}));
  renderCmd->add_option("--morph-t", render.morphT,
                        "With --view morph: 0 MC, 1 WC, 2 VRC, 2.5 homogeneous NPC, 3 NPC, 4 DC, or between")
      ->check(finiteIn(0, 4));
  renderCmd->add_option("--style", render.style,
                        "flat (object colours, unlit), shaded (lit by the scene's lights), wire (every edge), "
                        "hidden-line (hidden edges dashed, lecture notes figure 16.1) or hidden-removed (hidden "
                        "edges left out, figure 16.3)")
      ->check(choicesOf(allOf<Style>()));
  renderCmd->add_option("--theme", render.theme,
                        "dark (the screen's) or light (white ground, dark lines told apart by dashes and widths "
                        "as well as colour: for print and a bright lecture hall)")
      ->check(CLI::IsMember({"dark", "light"}));
  renderCmd->add_option("--size", render.size,
                        "WIDTHxHEIGHT of each view; default: the scene's device (the camera view is then "
                        "pixel-aligned with DC)");
  renderCmd->add_option("--out", render.out,
                        "PNG file to write, or an SVG file (vector lines of the wireframe styles wire, hidden-line, "
                        "hidden-removed; hidden-line unless --style says); default: vplab-VIEW.png. With --lesson: "
                        "the directory for its stills and index.md; with --animate: a .gif");
  CLI::Option* renderLessonOption =
      renderCmd->add_option("--lesson", render.lesson,
                            "Every step of a lesson (a file or a bundled one's name) as a picture with its caption "
                            "(--format png or svg, --view all unless given) and index.md, into the directory --out");
  renderCmd->add_option("--format", render.format, "With --lesson: png (default) or svg stills")
      ->check(CLI::IsMember({"png", "svg"}))
      ->needs(renderLessonOption);
  renderCmd->add_flag("--animate", render.animate,
                      "With --lesson: the steps and the moves between them as an animated GIF (--out x.gif); with "
                      "--view morph: the stage morph from MC to DC");
  renderCmd->add_option("--fps", render.fps, "With --animate: frames a second of the moves (default 15)")
      ->check(CLI::Range(1, 60));
  renderCmd->add_option("--hold", render.hold, "With --animate: seconds each step (each stage) is held (default 3)")
      ->check(finiteIn(0.02, 60));
  renderCmd->add_option("--backend", render.backend, "Headless OpenGL: auto (EGL, then OSMesa), egl or osmesa")
      ->check(choicesOf(allOf<Backend>()));
  renderCmd->add_option("--strategy", render.strategy, "Clipping strategy of the CPU overlays: npc, wc or divide-first")
      ->check(choicesOf(allOf<ClipStrategy>()));
  renderCmd->add_flag("--gl-debug", render.glDebug, "Turn on KHR_debug and fail on any OpenGL error");
  renderCmd->add_option("--ui-scale", render.uiScale,
                        "Scale the views' text, lines and markers as the viewer's UI scale does (a projector); "
                        "with --view ui also the panels' fonts and handles")
      ->check(finiteIn(0.5, 4));
  renderCmd->add_option("--lang", render.lang,
                        "The language of the views' labels (with --view ui also the panels'): en (default) or de")
      ->check(CLI::IsMember({"en", "de"}));
  renderCmd->add_option("--tab", render.tabs, "With --view ui: show this tab (repeatable): camera, scene, clipping, "
                                              "display, lecture (controls) or probe, matrices, depth (inspector)")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(kTabNames), std::end(kTabNames))));

  BenchOptions bench;
  std::string benchOnly;
  CLI::App* benchCmd = app.add_subcommand(
      "bench", "Measure, in one run on this machine: the CPU pipeline on ~1M triangles against a floor pass and a "
               "textbook baseline, on one core and on every core; frame times per view at 1280×720; the start-up of vplab render; the time "
               "from an input event to the updated frame; where the memory of the 1M-triangle scene goes");
  benchCmd->add_flag("--json", bench.json, "Print the report as JSON on stdout (progress goes to stderr)");
  benchCmd->add_option("--repetitions", bench.repetitions, "Rounds of the pipeline workloads (median reported)")
      ->check(CLI::Range(1, 100));
  benchCmd->add_option("--frames", bench.frames, "Frames per frame-time measurement")->check(CLI::Range(5, 10000));
  benchCmd->add_option("--only", benchOnly, "Comma-separated parts: pipeline, frames, startup, input, memory");
  bool benchMemory = false;
  benchCmd->add_flag("--memory", benchMemory,
                     "Only where the bytes of the 1M-triangle scene go, by structure, and the peak memory of the viewer "
                     "and of vplab render --view all (--only memory)");

  CLI::App* presetsCmd = app.add_subcommand(
      "presets", "List the bundled scenes (the viewer's File > Presets): each one's name, title and file");
  CLI::App* lessonsCmd = app.add_subcommand(
      "lessons", "List the bundled lessons (the viewer's File > Lessons): each one's name, title and file");

  addCourseCommands(app);  // exercise, grade (app/commands/course_commands.cpp)

  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // a subcommand that ran in its callback (exercise, grade) and set its status
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every usage error exits 2 (CLI11's own codes differ by kind).
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (dumpCmd->parsed()) return runDump(dump);
    if (presetsCmd->parsed()) return runPresets();
    if (lessonsCmd->parsed()) return runLessons();
    if (renderCmd->parsed()) {
      if (const std::string e = renderOutError(render.out, !render.lesson.empty(), render.animate); !e.empty()) {
        std::cerr << "vplab: error: --out: " << e << "\n";
        return 2;
      }
      render.styleGiven = renderCmd->count("--style") > 0;
      render.viewGiven = renderCmd->count("--view") > 0;
      return runRender(render);
    }
    if (benchCmd->parsed()) {
      for (size_t start = 0; start < benchOnly.size();) {
        const size_t comma = std::min(benchOnly.find(',', start), benchOnly.size());
        const std::string part = benchOnly.substr(start, comma - start);
        if (part != "pipeline" && part != "frames" && part != "startup" && part != "input" && part != "memory")
          throw Error("--only: \"" + part + "\" is not one of pipeline, frames, startup, input, memory");
        bench.only.push_back(part);
        start = comma + 1;
      }
      if (benchMemory) bench.only.push_back("memory");
      std::error_code ec;
      bench.executable = std::filesystem::read_symlink("/proc/self/exe", ec).string();
      if (ec) bench.executable = argv[0];
      return runBench(bench);
    }
    return runViewer(viewer);
  } catch (const Error& e) {
    std::cerr << "vplab: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "vplab: unexpected error: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace vplab
