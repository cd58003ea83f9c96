// Index: 1 documents  2 questions  3 each frame  4 the language  5 adding objects
#include "app/session/session.h"

#include "app/document/assets.h"
#include "app/text/catalogue.h"
#include "base/error.h"
#include "io/build_mesh.h"

#include <algorithm>
#include <utility>

namespace vplab {

Session::Session(ViewerModel& state, std::unique_ptr<FileChooser> chooser, Hooks hooks)
    : state_(state),
      hooks_(std::move(hooks)),
      files_(state, *this, std::move(chooser)),
      recovery_(state, *this),
      links_(state, *this),
      exercises_(state, *this) {}

// ---------------------------------------------------------------- 1 documents

void Session::newDocument() {
  unlessUnsaved([this] { startDocument(defaultScene()); });
}

void Session::startDocument(Scene scene, bool dirty) {
  loader_.cancel();  // an OBJ still loading for the previous document must not land in this one
  links_.forgetPending();
  state_.doc.replace(std::move(scene), dirty);
  state_.probe.reset();
  state_.selectedObject = 0;
  state_.stepThrough = {};
  state_.drag = {};
  state_.morphPlaying = false;
  state_.display = freshDisplay();
  state_.pipeline = kFreshPipeline;
  state_.display.world.orbit = defaultWorldOrbit(state_.doc.shown(), state_.worldAspect);
  state_.lesson.reset();  // a lesson opens its own document after this (openLesson)
  state_.lessonMarks.clear();
  exercises_.endFrame();  // what was typed last is kept; an exercise opens its own document after this
  state_.practice.reset();
  state_.check.reset();
  hooks_.changed();
}

DisplaySettings Session::freshDisplay() const {
  // The user's UI scale, aspect lock and antialiasing, the theme and the labels' language are
  // preferences, not choices for a scene, and stay.
  DisplaySettings d;
  d.theme = state_.display.theme;
  d.language = state_.display.language;
  d.camera.style = Style::shaded;
  return d;
}

LessonContext Session::lessonContext() const {
  LessonContext c;
  const std::filesystem::path assets = assetsDirectory();
  c.scenesDirectory = assets.empty() ? std::filesystem::path() : assets / "scenes";
  c.fresh = freshDisplay();
  c.worldAspect = state_.worldAspect;
  return c;
}

void Session::openLesson(const std::filesystem::path& file, size_t step, std::function<void(size_t steps)> beyond) {
  // Read (and checked) before anything is asked or replaced: a broken lesson changes nothing.
  std::optional<Lesson> lesson;
  try {
    lesson = loadLesson(file, lessonContext());
  } catch (const Error& e) {
    state_.setStatus(e.what(), true);
    return;
  }
  auto shared = std::make_shared<Lesson>(std::move(*lesson));
  unlessUnsaved([this, shared, step, beyond] {
    const size_t count = shared->steps.size();
    const size_t first = step < count ? step : beyond ? 0 : count - 1;
    startDocument(shared->steps[first].state.scene);
    // The caption box names the lesson: the status line says nothing, and the panels keep its rows
    // for the step's evidence (at 1.6 it took two).
    state_.setStatus("", false);
    state_.lesson.emplace(std::move(*shared), first);
    state_.lessonAspect = state_.worldAspect;
    if (step >= count && beyond) beyond(count);
    hooks_.changed();
  });
}

void Session::reframeLesson() {
  if (!state_.lesson || state_.doc.dirty()) return;
  const std::filesystem::path file = state_.lesson->lesson().file;
  try {
    loadLesson(file, lessonContext());  // it was read once: if it cannot be now, the lesson stays as it is
  } catch (const Error&) {
    return;
  }
  // The same lesson at the same step: what the status line says (a link's parts left out) stays.
  const std::string status = state_.status;
  const bool statusIsError = state_.statusIsError;
  openLesson(file, state_.lesson->step());
  state_.setStatus(status, statusIsError);
}

void Session::openScene(const std::filesystem::path& file) {
  loader_.start(file);
  links_.forgetPending();
  state_.setStatus(text::fill(language(), "opening {1} …", {file.string()}), false);
  hooks_.changed();
}

void Session::cancelLoading() {
  if (!loader_.busy()) return;
  state_.setStatus(text::fill(language(), "opening {1} cancelled; the open scene stays", {loader_.file().string()}), false);
  loader_.cancel();
  links_.forgetPending();
  hooks_.changed();
}

// ---------------------------------------------------------------- 2 questions

void Session::unlessUnsaved(std::function<void()> action) {
  if (!state_.doc.dirty()) {
    action();
    return;
  }
  pendingReplace_ = std::move(action);
}

void Session::discardChanges() {
  std::function<void()> replace = std::exchange(pendingReplace_, nullptr);
  if (replace) replace();
}

// ---------------------------------------------------------------- 3 each frame

bool Session::beginFrame() {
  if (state_.objectToLoad) {  // "+ OBJ mesh…" of the scene panel
    const std::filesystem::path& path = state_.doc.scene().path;
    loader_.startObject(std::move(*state_.objectToLoad), path.empty() ? std::filesystem::path() : path.parent_path());
    state_.objectToLoad.reset();
  }
  std::optional<SceneLoader::Loaded> loaded = loader_.poll();
  if (!loaded) return false;
  std::optional<Links::Pending> link = links_.takePending();
  if (loaded->scene) {
    const std::string file = loaded->scene->path.string();
    // The link's camera over the scene it names; one that is no camera is left out, said with the
    // link's other problems.
    std::vector<LinkProblem> problems = state_.linkProblems;
    if (link) loaded->scene->camera = links_.cameraOver(link->link.camera, loaded->scene->camera, problems);
    startDocument(std::move(*loaded->scene));
    state_.setStatus(text::fill(language(), "opened {1}", {file}), false);
    if (link) link->showViews();
    if (link && !problems.empty()) links_.say(problems);
  } else if (loaded->object) {  // one undo step, recorded at the end of this frame
    Scene& scene = state_.doc.scene();
    state_.setStatus(text::fill(language(), "added {1}", {loaded->object->file}), false);
    scene.objects.push_back(std::move(*loaded->object));
    state_.selectedObject = int(scene.objects.size()) - 1;
  } else {
    state_.setStatus(loaded->error, true);  // the open scene stays
  }
  return true;
}

void Session::endFrame(double now) {
  if (state_.quitRequested && !state_.doc.dirty()) state_.quitConfirmed = true;
  recovery_.endFrame(now);
  exercises_.endFrame();
}

std::optional<double> Session::wakeIn(double now) const {
  if (loader_.busy()) return 0.0;
  return recovery_.dueIn(now);
}

// ---------------------------------------------------------------- 4 start and the language

void Session::start(Start start) {
  state_.display.language = start.language;
  rememberLanguage_ = std::move(start.rememberLanguage);
  recovery_.offerRecoveries(std::move(start.recoveries));
  if (!start.autosaveDirectory.empty()) recovery_.enableAutosave(start.autosaveDirectory, kAutosaveDelay);
  exercises_.keepOn(std::move(start.answers));
}

void Session::chooseLanguage(Language lang) {
  state_.display.language = lang;
  if (state_.practice) setPracticeLanguage(*state_.practice, lang);
  if (!rememberLanguage_) return;
  try {
    rememberLanguage_(lang);
  } catch (const Error& e) {
    state_.setStatus(e.what(), true);
  }
}

// ---------------------------------------------------------------- 5 adding objects

void addObject(DocumentPart& d, EditPart& e, StatusPart& status, Shape shape, std::string file) {
  Scene& scene = d.doc.scene();
  SceneObject o;
  o.shape = shape;
  o.name = std::string(toString(shape)) + " " + std::to_string(scene.objects.size());
  o.file = std::move(file);
  o.segments = 24;
  o.color = {0.75, 0.75, 0.78};
  if (shape == Shape::polygon) o.vertices = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  o.transform.translate = scene.camera.vrp;  // where the camera looks
  if (shape == Shape::mesh) {  // read on the session's worker thread (app/document/loader.h)
    e.objectToLoad = std::move(o);
    return;
  }
  try {
    buildMesh(o, scene.path.empty() ? std::filesystem::path{} : scene.path.parent_path());
  } catch (const Error& err) {
    status.setStatus(err.what(), true);
    return;
  }
  scene.objects.push_back(std::move(o));
  e.selectedObject = int(scene.objects.size()) - 1;
}

}  // namespace vplab
