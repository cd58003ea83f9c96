// Index: 1 commands  2 each frame  3 dialogs  4 files and links  5 autosave and recovery  6 preferences
#include "app/ui/session.h"

#include "app/document/assets.h"
#include "app/ui/lesson_presenter.h"
#include "app/ui/panels.h"
#include "app/ui/widgets.h"
#include "base/error.h"
#include "io/scene_io.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>  // GetTopMostPopupModal

#include <algorithm>
#include <cctype>
#include <cmath>
#include <utility>
#include <cstdio>

namespace vplab {

namespace {

/// Where "save a copy" of a bundled scene starts: its name in the working directory.
std::filesystem::path copyName(const std::filesystem::path& bundled) {
  std::error_code ec;
  const std::filesystem::path cwd = std::filesystem::current_path(ec);
  return cwd / (bundled.empty() ? std::filesystem::path("lecture-scene.json") : bundled.filename());
}

}  // namespace

Session::Session(ViewerState& state, std::function<void()> changed) : state_(state), changed_(std::move(changed)) {}

void Session::setStatus(std::string message, bool error) {
  state_.status = std::move(message);
  state_.statusIsError = error;
}

// ---------------------------------------------------------------- 1 commands

void Session::newDocument() {
  unlessUnsaved([this] { startDocument(defaultScene()); });
}

// ---------------------------------------------------------------- 2 each frame

bool Session::beginFrame() {
  if (state_.objectToLoad) {  // "+ OBJ mesh…" of the scene panel
    const std::filesystem::path& path = state_.doc.scene().path;
    loader_.startObject(std::move(*state_.objectToLoad), path.empty() ? std::filesystem::path() : path.parent_path());
    state_.objectToLoad.reset();
  }
  std::optional<SceneLoader::Loaded> loaded = loader_.poll();
  if (!loaded) return false;
  std::optional<PendingLink> link = std::exchange(pendingLink_, std::nullopt);
  if (loaded->scene) {
    const std::string file = loaded->scene->path.string();
    try {
      if (link) loaded->scene->camera = link->link.camera.over(loaded->scene->camera);
    } catch (const Error& e) {
      setStatus(e.what(), true);  // as the link read at once would: nothing opened
      return true;
    }
    startDocument(std::move(*loaded->scene));
    setStatus(ui::tr(state_, "opened {1}", {file}), false);
    if (link) link->showViews();
  } else if (loaded->object) {  // one undo step, recorded at the end of this frame
    Scene& scene = state_.doc.scene();
    setStatus(ui::tr(state_, "added {1}", {loaded->object->file}), false);
    scene.objects.push_back(std::move(*loaded->object));
    state_.selectedObject = int(scene.objects.size()) - 1;
  } else {
    setStatus(loaded->error, true);  // the open scene stays
  }
  return true;
}

void Session::endFrame(double now) {
  if (!autosave_) return;
  // What else is on screen matters only to a file that will be written: not built every clean frame.
  if (state_.doc.dirty()) autosave_->update(state_.doc, now, recoveryView());
  else autosave_->update(state_.doc, now);
  if (autosave_->error() != autosaveError_) {  // say it once, not every frame
    autosaveError_ = autosave_->error();
    if (!autosaveError_.empty()) setStatus(autosaveError_, true);
  }
}

void Session::drawDialogs(float scale) {
  loadingWindow(scale);
  recoveryDialog();
  quitDialog();
  discardDialog();
  dialog_->draw(state_.display.language);
}

std::optional<double> Session::wakeIn(double now) const {
  if (loader_.busy() || askRecovery_) return 0.0;
  if (autosave_) return autosave_->dueIn(now);
  return std::nullopt;
}

// ---------------------------------------------------------------- 3 dialogs

bool Session::dialogOpen() const {
  return askRecovery_ || askDiscard_ || ImGui::GetTopMostPopupModal() != nullptr;
}

void Session::quitDialog() {
  if (state_.quitRequested && !state_.doc.dirty()) state_.quitConfirmed = true;
  const char* title = ui::tr(state_, "Unsaved changes###Unsaved changes");  // the popup's id in either language
  if (state_.quitRequested && state_.doc.dirty() && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted(ui::tr(state_, "The scene has unsaved changes. Save them before quitting?"));
  if (ImGui::Button(ui::tr(state_, "Save"))) {
    ImGui::CloseCurrentPopup();
    if (state_.doc.path().empty() || isBundled(state_.doc.path())) {
      state_.quitRequested = false;
      dialog_->open(ui::tr(state_, "Save a copy of the scene###Save a copy of the scene"), FileChooser::Mode::save, {".json"}, copyName(state_.doc.path()), [this](const std::filesystem::path& f) {
        saveScene(f);
        if (!state_.doc.dirty()) state_.quitConfirmed = true;
      });
    } else {
      saveScene(state_.doc.path());
      state_.quitConfirmed = !state_.doc.dirty();
      state_.quitRequested = state_.quitConfirmed;
    }
  }
  ImGui::SameLine();
  if (ImGui::Button(ui::tr(state_, "Discard them and quit"))) {
    ImGui::CloseCurrentPopup();
    state_.quitConfirmed = true;
  }
  ImGui::SameLine();
  if (ImGui::Button(ui::tr(state_, "Cancel"))) {
    ImGui::CloseCurrentPopup();
    state_.quitRequested = false;
  }
  ImGui::EndPopup();
}

void Session::unlessUnsaved(std::function<void()> action) {
  if (!state_.doc.dirty()) {
    action();
    return;
  }
  pendingReplace_ = std::move(action);
  askDiscard_ = true;
}

void Session::discardDialog() {
  const char* title = ui::tr(state_, "Discard unsaved changes?###Discard unsaved changes?");
  if (askDiscard_) {
    ImGui::OpenPopup(title);
    askDiscard_ = false;
  }
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::TextUnformatted(ui::tr(state_, "The scene has unsaved changes. They are lost if another scene is opened."));
  if (ImGui::Button(ui::tr(state_, "Discard them"))) {
    ImGui::CloseCurrentPopup();
    if (pendingReplace_) pendingReplace_();
    pendingReplace_ = nullptr;
  }
  ui::recordRect(state_, "discard.confirm");
  ImGui::SameLine();
  if (ImGui::Button(ui::tr(state_, "Keep editing"))) {
    ImGui::CloseCurrentPopup();
    pendingReplace_ = nullptr;
  }
  ImGui::EndPopup();
}

// ---------------------------------------------------------------- 1 commands (continued)

void Session::startDocument(Scene scene, bool dirty) {
  loader_.cancel();  // an OBJ still loading for the previous document must not land in this one
  pendingLink_.reset();
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
  changed_();
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

void Session::openLesson(const std::filesystem::path& file, size_t step) {
  // Read (and checked) before anything is asked or replaced: a broken lesson changes nothing.
  std::optional<Lesson> lesson;
  try {
    lesson = loadLesson(file, lessonContext());
  } catch (const Error& e) {
    setStatus(e.what(), true);
    return;
  }
  auto shared = std::make_shared<Lesson>(std::move(*lesson));
  unlessUnsaved([this, shared, step] {
    const size_t first = std::min(step, shared->steps.size() - 1);
    startDocument(shared->steps[first].state.scene);
    // The caption box names the lesson: the status line says nothing, and the panels keep its rows
    // for the step's evidence (at 1.6 it took two).
    setStatus("", false);
    state_.lesson.emplace(std::move(*shared), first);
    changed_();
  });
}

void Session::openScene(const std::filesystem::path& file) {
  loader_.start(file);
  pendingLink_.reset();
  setStatus(ui::tr(state_, "opening {1} …", {file.string()}), false);
  changed_();
}

void Session::cancelLoading() {
  if (!loader_.busy()) return;
  setStatus(ui::tr(state_, "opening {1} cancelled; the open scene stays", {loader_.file().string()}), false);
  loader_.cancel();
  pendingLink_.reset();
  changed_();
}

// A small window over the views while a scene loads: the views stay live underneath.
void Session::loadingWindow(float scale) {
  if (!loader_.busy()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(420 * scale, 0), ImGuiCond_Always);
  ImGui::Begin(ui::tr(state_, "Loading###Loading"), nullptr,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("%s", ui::tr(state_, "Reading and tessellating {1}", {loader_.file().filename().string()}).c_str());
  // The reader reports no fraction: the bar sweeps to show the work goes on, the time counts.
  const double t = loader_.elapsed();
  char label[32];
  std::snprintf(label, sizeof label, "%.1f s", t);
  ImGui::ProgressBar(float(std::fmod(t, 1.5) / 1.5), ImVec2(-1, 0), label);
  if (ImGui::Button(ui::tr(state_, "Cancel"))) cancelLoading();
  ui::recordRect(state_, "load.cancel");
  ImGui::End();
}

// ---------------------------------------------------------------- 4 files and links

bool Session::isBundled(const std::filesystem::path& file) const {
  if (file.empty()) return true;  // the built-in default scene
  std::error_code ec;
  for (const SceneFileInfo& p : state_.presets)
    if (std::filesystem::equivalent(p.file, file, ec)) return true;
  const std::filesystem::path assets = assetsDirectory();
  if (assets.empty()) return false;
  const auto dir = std::filesystem::weakly_canonical(assets / "scenes", ec);
  const auto parent = std::filesystem::weakly_canonical(file, ec).parent_path();
  return !ec && parent == dir;
}

void Session::saveAs() {
  dialog_->open(ui::tr(state_, "Save the scene###Save the scene"), FileChooser::Mode::save, {".json"}, isBundled(state_.doc.path()) ? copyName(state_.doc.path()) : state_.doc.path(),
               [this](const std::filesystem::path& f) { saveScene(f); });
}

void Session::saveScene(const std::filesystem::path& file) {
  if (dialog_->downloads()) {  // the browser: every save is a new download, named after the scene
    dialog_->open(ui::tr(state_, "Save the scene###Save the scene"), FileChooser::Mode::save, {".json"},
                  file.empty() ? std::filesystem::path("lecture-scene.json") : file.filename(),
                  [this](const std::filesystem::path& f) { writeScene(f); });
    return;
  }
  if (file.empty() || isBundled(file)) {  // never over a scene shipped with vplab: save a copy
    dialog_->open(ui::tr(state_, "Save a copy of the scene###Save a copy of the scene"), FileChooser::Mode::save, {".json"}, copyName(file),
                 [this](const std::filesystem::path& f) {
                   if (isBundled(f)) setStatus(ui::tr(state_, "{1} is a scene shipped with vplab: save the copy elsewhere", {f.string()}), true);
                   else saveScene(f);
                 });
    return;
  }
  writeScene(file);
}

void Session::writeScene(const std::filesystem::path& file) {
  try {
    state_.doc.save(file, /*carryMeshes=*/browser_);  // a scene downloaded from the page names no in-page file
    setStatus(ui::tr(state_, "saved {1}", {file.string()}), false);
  } catch (const Error& e) {
    setStatus(e.what(), true);
  }
}

void Session::chooseFileToOpen() {
  if (browser_) {
    dialog_->open(ui::tr(state_, "Open a scene or an OBJ mesh###Open a scene or an OBJ mesh"), FileChooser::Mode::open, {".json", ".obj"}, state_.doc.path(),
                  [this](const std::filesystem::path& f) { openFile(f); });
    return;
  }
  dialog_->open(ui::tr(state_, "Open a scene###Open a scene"), FileChooser::Mode::open, {".json"}, state_.doc.path(),
                [this](const std::filesystem::path& f) { unlessUnsaved([this, f] { openScene(f); }); });
}

void Session::openFile(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".obj") {
    unlessUnsaved([this, file] { openScene(file); });
    return;
  }
  ui::addObject(state_, Shape::mesh, file.string());  // as the scene panel's "+ OBJ mesh…"
  setStatus(ui::tr(state_, "adding {1} …", {file.string()}), false);
  changed_();
}

void Session::useFileChooser(std::unique_ptr<FileChooser> chooser, bool browser) {
  dialog_ = std::move(chooser);
  browser_ = browser;
}

UrlState Session::urlState() const {
  UrlState u;
  u.embed = state_.embedViews;
  // A bundled lesson's step is the whole state: the link names the lesson and the step.
  if (state_.lesson) {
    const std::filesystem::path& file = state_.lesson->lesson().file;
    const std::string name = file.stem().string();  // "02-view-orientation.en"
    std::error_code ec;
    const std::filesystem::path bundled = bundledLessonFile(name, state_.display.language);
    if (!bundled.empty() && std::filesystem::equivalent(bundled, file, ec)) {
      u.lesson = name;
      u.step = state_.lesson->step() + 1;
      return u;
    }
  }
  // The built-in scene is the bundled default.json (the same dump): a link names it as "default".
  if (state_.doc.path().empty()) u.scene = "default";
  else if (isBundled(state_.doc.path())) u.scene = state_.doc.path().stem().string();
  u.camera = cameraLinkOf(state_.doc.scene().camera);
  addViews(u);
  return u;
}

void Session::applyViews(const UrlState& link) {
  if (link.cameraStyle) state_.display.camera.style = *link.cameraStyle;
  if (link.worldStyle) state_.display.world.style = *link.worldStyle;
  if (link.npcStyle) state_.display.npc.style = *link.npcStyle;
  if (link.worldOrbit) state_.display.world.orbit = *link.worldOrbit;
  if (link.npcOrbit) state_.display.npc.orbit = *link.npcOrbit;
  if (link.strategy) state_.pipeline.strategy = *link.strategy;
}

void Session::addViews(UrlState& u) const {
  u.cameraStyle = state_.display.camera.style;
  u.worldStyle = state_.display.world.style;
  u.npcStyle = state_.display.npc.style;
  u.worldOrbit = state_.display.world.orbit;
  u.npcOrbit = state_.display.npc.orbit;
  u.strategy = state_.pipeline.strategy;
}

void Session::showUrlState(const UrlState& link, bool atStart) {
  if (link.embed != state_.embedViews) {
    state_.embedViews = link.embed;
    changed_();
  }
  if (!link.lesson.empty()) {
    const std::filesystem::path file = bundledLessonFile(link.lesson, state_.display.language);
    if (file.empty()) throw Error(ui::tr(state_, "the link's lesson \"{1}\" is not one of vplab's bundled lessons", {link.lesson}));
    const size_t step = link.step > 0 ? link.step - 1 : 0;
    std::error_code ec;
    if (state_.lesson && std::filesystem::equivalent(state_.lesson->lesson().file, file, ec)) {
      if (step >= state_.lesson->stepCount())
        throw Error(ui::tr(state_, "the link's step {1} is not one of the lesson's {2} steps",
                           {std::to_string(link.step), std::to_string(state_.lesson->stepCount())}));
      ui::goToStep(state_, step, ImGui::GetTime());  // the address followed a step: move there
      changed_();
      return;
    }
    openLesson(file, step);
    return;
  }
  auto showViews = [this, link] {
    applyViews(link);
    changed_();
  };
  const bool otherScene = !link.scene.empty() && link.scene != urlState().scene;
  if (otherScene || (atStart && !link.camera.empty())) {
    Scene scene = state_.doc.scene();
    if (otherScene) {
      const auto preset = std::find_if(state_.presets.begin(), state_.presets.end(),
                                       [&](const SceneFileInfo& p) { return p.file.stem() == link.scene; });
      if (preset == state_.presets.end()) throw Error(ui::tr(state_, "the link's scene \"{1}\" is not one of vplab's bundled scenes", {link.scene}));
      if (loader_.remote()) {
        // The page: its worker reads the scene while the page goes on (a million triangles took most
        // of a second); the link's camera and views apply when it is there (beginFrame).
        unlessUnsaved([this, file = preset->file, link, showViews] {
          loader_.start(file);
          pendingLink_ = PendingLink{link, showViews};
          changed_();
        });
        return;
      }
      scene = loadScene(preset->file);
    }
    scene.camera = link.camera.over(scene.camera);
    unlessUnsaved([this, scene = std::move(scene), showViews]() mutable {
      startDocument(std::move(scene));
      showViews();
    });
    return;
  }
  if (const Camera c = link.camera.over(state_.doc.scene().camera); c != state_.doc.scene().camera) state_.doc.scene().camera = c;
  showViews();
}

// ---------------------------------------------------------------- 5 autosave and recovery

void Session::enableAutosave(const std::filesystem::path& directory, double delaySeconds) {
  autosave_ = std::make_unique<Autosave>(directory, delaySeconds);
}

std::filesystem::path Session::writeRecoveryNow() {
  if (!autosave_ || !autosave_->writeNow(state_.doc, recoveryView())) return {};
  return autosave_->file();
}

void Session::endSession() {
  if (autosave_) autosave_->removeFile();
}

void Session::offerRecoveries(std::vector<Recovery> recoveries) {
  recoveries_ = std::move(recoveries);
  askRecovery_ = !recoveries_.empty();
}

namespace {

/// The kept scene's file, or the built-in scene's name (in German in the dative: it follows "an").
std::string sceneName(const ViewerState& s, const Recovery& r) {
  return r.scenePath.empty() ? ui::tr(s, "the default lecture scene") : r.scenePath.string();
}

}  // namespace

/// The i-th kept scene becomes this session's document; the others stay kept for the next start.
RecoveryView Session::recoveryView() const {
  RecoveryView v;
  if (state_.lesson) {
    v.lesson = state_.lesson->lesson().file;
    v.step = state_.lesson->step();
  }
  UrlState views;
  addViews(views);
  v.views = encodeUrlState(views);
  return v;
}

void Session::showRecoveredView(const RecoveryView& v) {
  // The lesson at its step, as it was left: settled (its step's state is not applied again over
  // the recovered scene). A lesson that cannot be read any more leaves the scene alone.
  if (!v.lesson.empty()) {
    try {
      Lesson lesson = loadLesson(v.lesson, lessonContext());
      const size_t step = std::min(v.step, lesson.steps.size() - 1);
      state_.lesson.emplace(std::move(lesson), step);
      state_.lesson->markSettled();
    } catch (const Error& e) {
      setStatus(e.what(), true);
    }
  }
  try {
    applyViews(decodeUrlState(v.views));
  } catch (const Error&) {
    // the views of a fresh start
  }
  // The camera in the fields as it was typed; the views keep the scene's, the last valid one.
  if (v.editedCamera) state_.doc.scene().camera = *v.editedCamera;
  // And the objects' transforms as typed (an index beyond the scene is someone else's file: ignored).
  for (const auto& [index, transform] : v.editedTransforms)
    if (index < state_.doc.scene().objects.size()) state_.doc.scene().objects[index].transform = transform;
  if (v.editedCamera || !v.editedTransforms.empty()) state_.doc.endFrame(false);
}

void Session::recover(size_t i) {
  const Recovery r = recoveries_[i];
  try {
    startDocument(Autosave::load(r), /*dirty=*/true);
    showRecoveredView(Autosave::loadView(r));
    Autosave::discard(r);  // this session's autosave keeps them from now on
    if (autosave_) autosave_->writeNow(state_.doc, recoveryView());
    const size_t others = recoveries_.size() - 1;
    const std::string name = sceneName(state_, r), count = std::to_string(others);
    if (others == 0) setStatus(ui::tr(state_, "recovered the unsaved changes of {1}", {name}), false);
    else if (others == 1 && browser_)
      setStatus(ui::tr(state_, "recovered the unsaved changes of {1}; 1 other kept scene is offered in the next tab or visit", {name}), false);
    else if (others == 1)
      setStatus(ui::tr(state_, "recovered the unsaved changes of {1}; 1 other kept scene is offered at the next start", {name}), false);
    else if (browser_)
      setStatus(ui::tr(state_, "recovered the unsaved changes of {1}; {2} other kept scenes are offered in the next tab or visit", {name, count}), false);
    else
      setStatus(ui::tr(state_, "recovered the unsaved changes of {1}; {2} other kept scenes are offered at the next start", {name, count}), false);
  } catch (const Error& e) {
    setStatus(e.what(), true);  // the file stays for another try
  }
  recoveries_.clear();
}

void Session::recoveryDialog() {
  const char* title = ui::tr(state_, "Recover unsaved changes?###Recover unsaved changes?");
  if (askRecovery_) {
    ImGui::OpenPopup(title);
    askRecovery_ = false;
  }
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  auto line = [](const std::string& text) { ImGui::TextUnformatted(text.c_str()); };
  if (recoveries_.size() == 1) {
    const Recovery& r = recoveries_.front();
    const std::string name = sceneName(state_, r);
    if (browser_) {
      line(ui::tr(state_, "A visit to vplab was left with unsaved changes of {1};", {name}));
      line(ui::tr(state_, "they were kept at {1}.", {r.savedAt}));
    } else {
      line(ui::tr(state_, "vplab did not end normally with unsaved changes of {1};", {name}));
      line(ui::tr(state_, "they were kept at {1} ({2}).", {r.savedAt, r.file.string()}));
    }
  } else {
    const std::string count = std::to_string(recoveries_.size());
    if (browser_) {
      line(ui::tr(state_, "{1} tabs or visits were left with unsaved changes. Recover one here;", {count}));
      ImGui::TextUnformatted(ui::tr(state_, "the others stay kept and are offered in the next tab or visit."));
    } else {
      line(ui::tr(state_, "{1} sessions were left with unsaved changes. Recover one here;", {count}));
      ImGui::TextUnformatted(ui::tr(state_, "the others stay kept and are offered at the next start."));
    }
  }
  std::optional<size_t> recovered, discarded;
  // The newest few, so that the dialog fits a screen after many crashes; the others come up as
  // these are discarded.
  constexpr size_t kListed = 6;
  const size_t listed = std::min(recoveries_.size(), kListed);
  for (size_t i = 0; i < listed; ++i) {
    ImGui::PushID(int(i));
    if (recoveries_.size() > 1) {
      ImGui::Separator();
      line(ui::tr(state_, "{1}, kept at {2}", {sceneName(state_, recoveries_[i]), recoveries_[i].savedAt}));
    }
    if (ImGui::Button(ui::tr(state_, "Recover them"))) recovered = i;
    const std::string suffix = i == 0 ? std::string() : "." + std::to_string(i);
    ui::recordRect(state_, ("recovery.recover" + suffix).c_str());
    ImGui::SameLine();
    if (ImGui::Button(ui::tr(state_, "Discard them"))) discarded = i;
    ui::recordRect(state_, ("recovery.discard" + suffix).c_str());
    ImGui::PopID();
  }
  if (recoveries_.size() > listed) {
    ImGui::Separator();
    line(ui::tr(state_, "and {1} older ones, listed as these are discarded", {std::to_string(recoveries_.size() - listed)}));
  }
  if (recoveries_.size() > 1) {
    ImGui::Separator();
    if (ImGui::Button(ui::tr(state_, "Later"))) {
      recoveries_.clear();  // all stay kept
      setStatus(browser_ ? ui::tr(state_, "the kept scenes are offered again in the next tab or visit")
                         : ui::tr(state_, "the kept scenes are offered again at the next start"),
                false);
    }
    ui::recordRect(state_, "recovery.later");
  }
  if (recovered) recover(*recovered);
  if (discarded) {
    Autosave::discard(recoveries_[*discarded]);
    recoveries_.erase(recoveries_.begin() + std::ptrdiff_t(*discarded));
  }
  if (recoveries_.empty()) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

// ---------------------------------------------------------------- 6 preferences

void Session::chooseLanguage(Language lang) {
  state_.display.language = lang;
  if (!rememberLanguage_) return;
  try {
    rememberLanguage_(lang);
  } catch (const Error& e) {
    setStatus(e.what(), true);
  }
}

}  // namespace vplab
