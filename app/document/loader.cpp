#include "app/document/loader.h"

#include "base/error.h"
#include "io/build_mesh.h"
#include "io/read_file.h"
#include "io/scene_io.h"

#include <system_error>

namespace vplab {

namespace {

/// With the worker: what a scene may hold to be read at once rather than sent (a bundled lecture
/// scene, a small OBJ): the worker's start and the meshes' way back cost more than such a scene's
/// reading. Anything over it (or any error, which the worker then reports with the full limits)
/// goes to the worker.
Limits atOnceLimits() {
  Limits l = kDefaultLimits;
  l.faces = l.vertices = 50'000;
  l.corners = 200'000;
  l.objFileBytes = std::uintmax_t(2) << 20;
  return l;
}

}  // namespace

SceneLoader::SceneLoader() : reader_([](const std::filesystem::path& f) { return loadScene(f); }) {}

SceneLoader::~SceneLoader() {
  cancel();
  for (auto& j : abandoned_)
    if (j->worker.joinable()) j->worker.join();
}

void SceneLoader::start(std::filesystem::path file) {
  if (remote_) {
    auto job = std::make_unique<Job>();
    job->file = file;
    job->source = file.string();
    job->baseDir = file.parent_path();
    try {
      job->text = readRegularFile(file, kDefaultLimits.sceneFileBytes, "scene file");
    } catch (const Error& e) {
      job->result.error = e.what();
    }
    try {
      if (job->result.error.empty()) {
        Scene scene = parseScene(job->text, job->source, job->baseDir, atOnceLimits());
        scene.path = file;
        job->result.scene = std::move(scene);
      }
    } catch (const Error&) {
      // Over the small budget (or wrong): the worker reads it with the full limits.
    }
    send(std::move(job));
    return;
  }
  run(file, [reader = reader_, file](Loaded& out) { out.scene = reader(file); });
}

void SceneLoader::startObject(SceneObject object, std::filesystem::path baseDir) {
  const std::filesystem::path file = object.file;
  if (remote_) {
    auto job = std::make_unique<Job>();
    job->file = file;
    job->source = file.string();
    job->baseDir = std::move(baseDir);
    try {
      SceneObject built = object;
      buildMesh(built, job->baseDir, atOnceLimits());
      job->result.object = std::move(built);
    } catch (const Error&) {
      // Over the small budget: the worker builds it, given the object as the only one of a scene
      // (what a scene file would give it).
      Scene one = defaultScene();
      one.objects = {object};
      one.objects[0].mesh.reset();
      job->text = sceneToJson(one);
      job->object = std::move(object);
    }
    send(std::move(job));
    return;
  }
  run(file, [object = std::move(object), baseDir = std::move(baseDir)](Loaded& out) mutable {
    buildMesh(object, baseDir);
    out.object = std::move(object);
  });
}

void SceneLoader::send(std::unique_ptr<Job> job) {
  cancel();
  job->started = std::chrono::steady_clock::now();
  job->id = ++lastId_;
  // Read at once (or not readable at all): nothing to send.
  if (!job->result.error.empty() || job->result.scene || job->result.object) job->done.store(true);
  else remote_(job->id, job->text, job->source, job->baseDir);
  job_ = std::move(job);
}

void SceneLoader::deliver(uint64_t id, BuiltMeshes meshes, std::string error) {
  if (!job_ || job_->id != id || job_->done.load()) return;  // cancelled or replaced: dropped
  Job& j = *job_;
  if (!error.empty()) {
    j.result.error = std::move(error);
    j.text.clear();
  } else {
    j.arrived = std::move(meshes);
  }
  j.done.store(true);
}

void SceneLoader::readWithArrivedMeshes(Job& j) {
  try {
    Scene scene = parseScene(j.text, j.source, j.baseDir, kDefaultLimits, &*j.arrived);
    if (j.object) {
      if (scene.objects.size() != 1) throw Error(j.source + ": the worker read " + std::to_string(scene.objects.size()) + " objects");
      j.object->mesh = scene.objects[0].mesh;
      j.result.object = std::move(j.object);
    } else {
      scene.path = j.file;
      j.result.scene = std::move(scene);
    }
  } catch (const Error& e) {
    j.result.error = e.what();
  }
  j.arrived.reset();
  j.text.clear();
}

void SceneLoader::run(std::filesystem::path file, std::function<void(Loaded&)> work) {
  cancel();
  auto job = std::make_unique<Job>();
  job->file = std::move(file);
  job->started = std::chrono::steady_clock::now();
  Job* j = job.get();  // owned by job_ or abandoned_ until the worker has been joined
  auto load = [j, work = std::move(work)] {
    try {
      work(j->result);
    } catch (const std::exception& e) {  // vplab::Error names the file; anything else gets named here
      j->result.error = dynamic_cast<const Error*>(&e) ? e.what() : j->file.string() + ": " + e.what();
    }
    j->done.store(true, std::memory_order_release);
  };
  try {
    j->worker = std::thread(load);
  } catch (const std::system_error&) {
    load();  // no thread can be started (the browser build has none): the load runs here, at once
  }
  job_ = std::move(job);
}

void SceneLoader::cancel() {
  // A thread still running is joined once it is done; a worker's request is simply forgotten (its
  // answer will be dropped).
  if (job_ && job_->worker.joinable()) abandoned_.push_back(std::move(job_));
  job_.reset();
  reap();
}

void SceneLoader::reap() {
  for (auto it = abandoned_.begin(); it != abandoned_.end();) {
    if ((*it)->done.load(std::memory_order_acquire)) {
      if ((*it)->worker.joinable()) (*it)->worker.join();
      it = abandoned_.erase(it);
    } else {
      ++it;
    }
  }
}

const std::filesystem::path& SceneLoader::file() const {
  static const std::filesystem::path none;
  return job_ ? job_->file : none;
}

double SceneLoader::elapsed() const {
  if (!job_) return 0;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - job_->started).count();
}

std::optional<SceneLoader::Loaded> SceneLoader::poll() {
  reap();
  if (!job_ || !job_->done.load(std::memory_order_acquire)) return std::nullopt;
  if (job_->worker.joinable()) job_->worker.join();
  std::unique_ptr<Job> job = std::move(job_);
  if (job->arrived) readWithArrivedMeshes(*job);
  return std::move(job->result);
}

}  // namespace vplab
