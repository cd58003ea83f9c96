#include "app/session/scene_files.h"

#include "app/session/session.h"
#include "app/text/catalogue.h"
#include "base/error.h"

#include <cctype>

namespace vplab {

namespace {

/// Where "save a copy" of a bundled scene starts: its name in the working directory.
std::filesystem::path copyName(const std::filesystem::path& bundled) {
  std::error_code ec;
  const std::filesystem::path cwd = std::filesystem::current_path(ec);
  return cwd / (bundled.empty() ? std::filesystem::path("lecture-scene.json") : bundled.filename());
}

}  // namespace

SceneFiles::SceneFiles(ViewerModel& state, Session& session, std::unique_ptr<FileChooser> chooser)
    : state_(state), session_(session), dialog_(std::move(chooser)), presets_(listPresetScenes()) {
  if (!dialog_) throw Error("SceneFiles: no file chooser");
}

void SceneFiles::chooseFileToOpen() {
  if (browser_) {
    dialog_->open(text::Text("Open a scene or an OBJ mesh###Open a scene or an OBJ mesh").in(language()), FileChooser::Mode::open, {".json", ".obj"}, state_.doc.path(),
                  [this](const std::filesystem::path& f) { openFile(f); });
    return;
  }
  dialog_->open(text::Text("Open a scene###Open a scene").in(language()), FileChooser::Mode::open, {".json"}, state_.doc.path(),
                [this](const std::filesystem::path& f) { session_.unlessUnsaved([this, f] { session_.openScene(f); }); });
}

void SceneFiles::openFile(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".obj") {
    session_.unlessUnsaved([this, file] { session_.openScene(file); });
    return;
  }
  addObject(state_, state_, state_, Shape::mesh, file.string());  // as the scene panel's "+ OBJ mesh…"
  state_.setStatus(text::fill(language(), "adding {1} …", {file.string()}), false);
  session_.hooks().changed();
}

void SceneFiles::saveAs() {
  dialog_->open(text::Text("Save the scene###Save the scene").in(language()), FileChooser::Mode::save, {".json"}, isBundled(state_.doc.path()) ? copyName(state_.doc.path()) : state_.doc.path(),
               [this](const std::filesystem::path& f) { saveScene(f); });
}

void SceneFiles::saveScene(const std::filesystem::path& file) {
  if (dialog_->downloads()) {  // the browser: every save is a new download, named after the scene
    dialog_->open(text::Text("Save the scene###Save the scene").in(language()), FileChooser::Mode::save, {".json"},
                  file.empty() ? std::filesystem::path("lecture-scene.json") : file.filename(),
                  [this](const std::filesystem::path& f) { writeScene(f); });
    return;
  }
  if (file.empty() || isBundled(file)) {  // never over a scene shipped with vplab: save a copy
    dialog_->open(text::Text("Save a copy of the scene###Save a copy of the scene").in(language()), FileChooser::Mode::save, {".json"}, copyName(file),
                 [this](const std::filesystem::path& f) {
                   if (isBundled(f)) state_.setStatus(text::fill(language(), "{1} is a scene shipped with vplab: save the copy elsewhere", {f.string()}), true);
                   else saveScene(f);
                 });
    return;
  }
  writeScene(file);
}

void SceneFiles::writeScene(const std::filesystem::path& file) {
  try {
    state_.doc.save(file, /*carryMeshes=*/browser_);  // a scene downloaded from the page names no in-page file
    state_.setStatus(text::fill(language(), "saved {1}", {file.string()}), false);
  } catch (const Error& e) {
    state_.setStatus(e.what(), true);
  }
}

bool SceneFiles::isBundled(const std::filesystem::path& file) const {
  if (file.empty()) return true;  // the built-in default scene
  std::error_code ec;
  for (const SceneFileInfo& p : presets_)
    if (std::filesystem::equivalent(p.file, file, ec)) return true;
  const std::filesystem::path assets = assetsDirectory();
  if (assets.empty()) return false;
  const auto dir = std::filesystem::weakly_canonical(assets / "scenes", ec);
  const auto parent = std::filesystem::weakly_canonical(file, ec).parent_path();
  return !ec && parent == dir;
}

void SceneFiles::useFileChooser(std::unique_ptr<FileChooser> chooser, bool browser) {
  dialog_ = std::move(chooser);
  browser_ = browser;
}

void SceneFiles::saveBeforeQuitting() {
  if (state_.doc.path().empty() || isBundled(state_.doc.path())) {
    state_.quitRequested = false;
    dialog_->open(text::Text("Save a copy of the scene###Save a copy of the scene").in(language()), FileChooser::Mode::save,
                  {".json"}, copyName(state_.doc.path()), [this](const std::filesystem::path& f) {
                    saveScene(f);
                    if (!state_.doc.dirty()) state_.quitConfirmed = true;
                  });
    return;
  }
  saveScene(state_.doc.path());
  state_.quitConfirmed = !state_.doc.dirty();
  state_.quitRequested = state_.quitConfirmed;
}

}  // namespace vplab
