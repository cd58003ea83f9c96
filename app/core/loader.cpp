#include "app/core/loader.h"

#include "pipeline/error.h"
#include "io/scene_io.h"
#include "io/build_mesh.h"

#include <system_error>

namespace vplab {

SceneLoader::SceneLoader() : reader_([](const std::filesystem::path& f) { return loadScene(f); }) {}

SceneLoader::~SceneLoader() {
  cancel();
  for (auto& j : abandoned_)
    if (j->worker.joinable()) j->worker.join();
}

void SceneLoader::start(std::filesystem::path file) {
  run(file, [reader = reader_, file](Loaded& out) { out.scene = reader(file); });
}

void SceneLoader::startObject(SceneObject object, std::filesystem::path baseDir) {
  const std::filesystem::path file = object.file;
  run(file, [object = std::move(object), baseDir = std::move(baseDir)](Loaded& out) mutable {
    buildMesh(object, baseDir);
    out.object = std::move(object);
  });
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
  if (job_) abandoned_.push_back(std::move(job_));
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
  return std::move(job->result);
}

}  // namespace vplab
