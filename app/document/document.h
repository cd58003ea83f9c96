// The scene being edited: its file, whether it has unsaved changes, the undo and redo history of
// every parameter change, and the last valid camera (the views keep showing it while the camera
// being edited is invalid, so nothing on screen is ever NaN).
#pragma once

#include "pipeline/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vplab {

class Document {
 public:
  explicit Document(Scene scene);

  /// The scene as edited (its camera may be invalid).
  Scene& scene() { return scene_; }
  const Scene& scene() const { return scene_; }
  /// The scene the views show: the edited one, or while that cannot be run (an invalid camera or
  /// transform), the last one that could.
  const Scene& shown() const { return shown_; }
  /// Why the edited scene cannot be run (sceneError); empty when it can.
  const std::string& error() const { return error_; }

  /// Call once per frame after the UI may have edited scene(): validates the camera and, unless an
  /// edit is still under way (a drag), records the change as one undo step.
  void endFrame(bool editInProgress);

  /// Ends the current undo step at `before` (the scene as it was when the next edit began).
  void recordStep(const Scene& before);

  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  void undo();
  void redo();

  bool dirty() const { return dirty_; }
  /// The scene is one a file reproduces (a lesson's step, app/lessons/lesson.h): nothing would be lost,
  /// so quitting need not ask. The history stays.
  void markClean() { dirty_ = false; }
  const std::filesystem::path& path() const { return scene_.path; }
  /// Replaces the scene (open, preset, New, a recovered autosave): a new document with an empty
  /// history, clean unless `dirty` (a recovered scene still has its unsaved changes).
  void replace(Scene scene, bool dirty = false);
  /// Writes the scene atomically (app/document/atomic_file.h); on success it is no longer dirty. Throws
  /// vplab::Error and leaves the file as it was. `carryMeshes`: the file carries its meshes' OBJ
  /// text (io/scene_io.h carryingItsMeshes; the page's downloads), the document keeps its files.
  void save(const std::filesystem::path& file, bool carryMeshes = false);

  /// Counts replace(): a frame that began with another document must not record an undo step
  /// between the two scenes.
  unsigned generation() const { return generation_; }
  /// Counts every recorded change (edit steps, undo, redo, replace, save): the autosave compares it.
  unsigned revision() const { return revision_; }
  /// Counts the changes of shown(), recorded or still under way (a drag): the CPU pipeline runs
  /// again when it changes.
  unsigned shownRevision() const { return shownRevision_; }

 private:
  void refreshShown();

  Scene scene_;
  Scene stable_;  // the scene as of the last recorded step
  Scene shown_;
  std::string error_;
  std::vector<Scene> undo_, redo_;
  bool dirty_ = false;
  unsigned generation_ = 0, revision_ = 0, shownRevision_ = 0;
  static constexpr size_t kMaxHistory = 500;
};

}  // namespace vplab
