// The page's loader: a second, small WebAssembly module (io/ and pipeline/, no GL, no ImGui) that
// runs in a Web Worker (loader-worker.js) and builds a scene's meshes, so that the page's own
// thread never waits for a large scene to be read and tessellated (docs/measured.md "Large scenes in
// the page"; app/document/loader.h, SceneLoader::useRemote). Threads in the page itself would need
// cross-origin isolation headers that a course page cannot count on; a worker needs none.
//
// The worker holds the bundled assets (preloaded, as the page's module does) and a copy of every
// file the page was given (/uploads, sent to it as they arrive), so a scene's OBJ files resolve the
// same on both sides. It parses the scene's text with every check the desktop makes, and hands back
// each object's mesh as plain arrays; the page parses the same text again with them.
#include "io/scene_io.h"
#include "base/error.h"

#include <emscripten/emscripten.h>

#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <string_view>

namespace {

/// One answer, owned by JavaScript between vplab_loader_parse and vplab_loader_free.
struct Answer {
  std::string error;
  vplab::Scene scene;
};

}  // namespace

extern "C" {

/// Parses `length` bytes of scene text at `text`, naming it `source` in messages and resolving mesh
/// files in `baseDir`; builds every mesh. Never throws: the error is in the answer.
EMSCRIPTEN_KEEPALIVE Answer* vplab_loader_parse(const char* text, size_t length, const char* source, const char* baseDir) {
  auto answer = std::make_unique<Answer>();
  try {
    answer->scene = vplab::parseScene(std::string_view(text, length), source, baseDir);
  } catch (const std::exception& e) {
    answer->error = e.what();
  }
  return answer.release();
}

EMSCRIPTEN_KEEPALIVE const char* vplab_loader_error(const Answer* a) { return a->error.c_str(); }

EMSCRIPTEN_KEEPALIVE size_t vplab_loader_objects(const Answer* a) { return a->error.empty() ? a->scene.objects.size() : 0; }

/// Object `i`'s mesh as one of five arrays: 0 positions (3 doubles a vertex), 1 indices (uint32),
/// 2 face starts (uint32), 3 normals (3 doubles each, none for flat shading), 4 normal indices (uint32
/// a corner, or none: one normal a vertex). Returns the address; its size in bytes goes to *bytes.
EMSCRIPTEN_KEEPALIVE const void* vplab_loader_array(const Answer* a, size_t i, int which, size_t* bytes) {
  *bytes = 0;
  if (i >= vplab_loader_objects(a) || !a->scene.objects[i].mesh) return nullptr;
  const vplab::Mesh& m = *a->scene.objects[i].mesh;
  switch (which) {
    case 0: *bytes = m.positions.size() * sizeof(vplab::Vec3); return m.positions.data();
    case 1: *bytes = m.indices.size() * sizeof(uint32_t); return m.indices.data();
    case 2: *bytes = m.faceStart.size() * sizeof(uint32_t); return m.faceStart.data();
    case 3: *bytes = m.normals.size() * sizeof(vplab::Vec3); return m.normals.data();
    case 4: *bytes = m.normalIndices.size() * sizeof(uint32_t); return m.normalIndices.data();
    default: return nullptr;
  }
}

EMSCRIPTEN_KEEPALIVE void vplab_loader_free(Answer* a) { delete a; }

}  // extern "C"
