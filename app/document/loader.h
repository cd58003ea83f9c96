// Opening a scene, or adding an OBJ mesh to it, without freezing the window: the file is read and
// its meshes tessellated on a worker thread while the viewer keeps drawing (a progress bar with
// Cancel). A 1M-triangle OBJ takes seconds to load; the UI stays live all the while.
//
// Cancel returns at once and keeps the open scene. The reader (io/scene_io.h) cannot be
// interrupted, so a cancelled load runs on to its end in the background and its result is
// dropped; the loader joins it on destruction.
//
// The page has no threads: there the meshes are built by a Web Worker (useRemote). A small scene
// (50 000 faces, an OBJ up to 2 MiB) is still read at once; a larger one is handed to the worker as
// text. The worker parses the text and builds every mesh; its meshes come back (deliver), and the
// text is parsed again here with them, which takes milliseconds where building a million-triangle
// mesh took most of a second.
#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "io/scene_io.h"
#include "pipeline/scene.h"

namespace vplab {

class SceneLoader {
 public:
  /// Reads a scene file (loadScene; tests give one they control). Runs on the worker thread.
  using Reader = std::function<Scene(const std::filesystem::path&)>;

  SceneLoader();
  /// For loads started from now on.
  void setReader(Reader reader) { reader_ = std::move(reader); }
  ~SceneLoader();
  SceneLoader(const SceneLoader&) = delete;
  SceneLoader& operator=(const SceneLoader&) = delete;

  /// Hands a scene's text to the page's worker, which answers through deliver(id, …).
  using Remote = std::function<void(uint64_t id, const std::string& text, const std::string& source,
                                    const std::filesystem::path& baseDir)>;
  /// Builds meshes with `send`'s worker from now on instead of a thread.
  void useRemote(Remote send) { remote_ = std::move(send); }
  bool remote() const { return bool(remote_); }
  /// The worker's answer to request `id`: the meshes of its text's objects in order, or the error
  /// that stopped it. An answer to a request no longer under way (cancelled, replaced) is dropped.
  /// It is only kept here: the text is read again with the meshes in the next poll, so the answer's
  /// arrival (the worker's message) and that reading are two tasks, not one long one.
  void deliver(uint64_t id, BuiltMeshes meshes, std::string error);

  /// Starts reading `file` (a load already running is cancelled).
  void start(std::filesystem::path file);
  /// Starts building `object`'s mesh (buildMesh; OBJ files relative to `baseDir`).
  void startObject(SceneObject object, std::filesystem::path baseDir);
  /// Drops the running load; the open scene stays.
  void cancel();
  bool busy() const { return job_ != nullptr; }
  const std::filesystem::path& file() const;
  /// Seconds since the running load started.
  double elapsed() const;

  /// A finished load: the scene or the object with its mesh, or the error naming the file.
  struct Loaded {
    std::optional<Scene> scene;
    std::optional<SceneObject> object;
    std::string error;
  };
  /// The finished load, once. Empty while busy or idle.
  std::optional<Loaded> poll();

 private:
  struct Job {
    std::filesystem::path file;
    // With the worker: the request, kept to be parsed again with the meshes that come back.
    uint64_t id = 0;
    std::string text, source;
    std::filesystem::path baseDir;
    std::optional<SceneObject> object;  // startObject's (its mesh comes back as the text's only one)
    std::optional<BuiltMeshes> arrived;  // the worker's meshes (deliver), read with the text in poll
    std::chrono::steady_clock::time_point started;
    std::atomic<bool> done{false};
    Loaded result;  // written by the worker before `done`
    std::thread worker;
  };
  Reader reader_;
  Remote remote_;
  uint64_t lastId_ = 0;
  std::unique_ptr<Job> job_;
  std::vector<std::unique_ptr<Job>> abandoned_;  // cancelled, still running: joined when done
  void reap();
  void run(std::filesystem::path file, std::function<void(Loaded&)> work);
  void send(std::unique_ptr<Job> job);
  static void readWithArrivedMeshes(Job& j);
};

}  // namespace vplab
