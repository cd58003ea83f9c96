#include "app/document/document.h"

#include "app/document/atomic_file.h"
#include "io/scene_io.h"

namespace vplab {

Document::Document(Scene scene) : scene_(std::move(scene)), stable_(scene_), shown_(scene_) { refreshShown(); }

void Document::refreshShown() {
  if (auto e = sceneError(scene_)) {
    error_ = *e;  // keep showing the last scene that could be run
  } else {
    error_.clear();
    shown_ = scene_;
    ++shownRevision_;
  }
}

void Document::endFrame(bool editInProgress) {
  // The one comparison of the edited scene per frame: the panels edit scene() in place.
  if (!error_.empty() || !(scene_ == shown_)) refreshShown();
  if (editInProgress || scene_ == stable_) return;
  undo_.push_back(std::move(stable_));
  if (undo_.size() > kMaxHistory) undo_.erase(undo_.begin());
  redo_.clear();
  stable_ = scene_;
  dirty_ = true;
  ++revision_;
}

void Document::recordStep(const Scene& before) {
  if (before == stable_) return;
  undo_.push_back(std::move(stable_));
  if (undo_.size() > kMaxHistory) undo_.erase(undo_.begin());
  redo_.clear();
  stable_ = before;
  dirty_ = true;
  ++revision_;
}

void Document::undo() {
  if (undo_.empty()) return;
  redo_.push_back(std::move(scene_));
  scene_ = std::move(undo_.back());
  undo_.pop_back();
  stable_ = scene_;
  dirty_ = true;
  ++revision_;
  refreshShown();
}

void Document::redo() {
  if (redo_.empty()) return;
  undo_.push_back(std::move(scene_));
  scene_ = std::move(redo_.back());
  redo_.pop_back();
  stable_ = scene_;
  dirty_ = true;
  ++revision_;
  refreshShown();
}

void Document::replace(Scene scene, bool dirty) {
  scene_ = std::move(scene);
  stable_ = scene_;
  shown_ = scene_;
  undo_.clear();
  redo_.clear();
  dirty_ = dirty;
  ++generation_;
  ++revision_;
  refreshShown();
}

void Document::save(const std::filesystem::path& file, bool carryMeshes) {
  writeFileAtomically(file, sceneToJson(carryMeshes ? carryingItsMeshes(scene_) : scene_));
  scene_.path = file;
  stable_.path = file;
  shown_.path = file;
  dirty_ = false;
  ++revision_;
}

}  // namespace vplab
