// An OpenGL 3.3 core context behind one small interface, one file per backend (as Filament's
// PlatformEGLHeadless / PlatformOSMesa): a GLFW window for the viewer, EGL surfaceless (the default
// headless backend) and OSMesa (the fallback). GL functions come from GLAD in multi-context mode:
// each context owns its GladGLContext, so no function pointers are global.
#pragma once

#include "base/enum_table.h"

#include <array>
#include <glad/gl.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

enum class Backend { automatic, egl, osmesa };
inline constexpr EnumTable<Backend, 3> kBackendNames = {{{Backend::automatic, "auto"}, {Backend::egl, "egl"}, {Backend::osmesa, "osmesa"}}};
constexpr const auto& namesOf(Backend) { return kBackendNames; }

/// Errors the KHR_debug callback reported (type ERROR or severity HIGH), collected per context.
struct GlDebugLog {
  std::vector<std::string> errors;
};

class GlContext {
 public:
  virtual ~GlContext() = default;
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  virtual std::string_view backend() const = 0;  // "egl", "osmesa", "glfw"
  virtual void makeCurrent() = 0;
  /// A second context that shares this one's objects (textures, buffers; not vertex arrays), for a
  /// render thread (app/render/view_worker.h); null when the backend cannot make one. Made on the
  /// calling thread, which this context stays current on.
  virtual std::unique_ptr<GlContext> createShared() { return nullptr; }
  /// Makes no context current on the calling thread (a render thread does before it ends).
  virtual void releaseCurrent() {}
  /// Whether glGetError waits for the GPU to run every draw queued before it (WebGL's round trip to
  /// the browser's GPU process): then a frame's errors are read later (app/render/frame_errors.h).
  virtual bool readingErrorsWaits() const { return false; }

  const GladGLContext& gl() const { return gl_; }
  /// "llvmpipe (LLVM 15.0.6, 256 bits) — 4.5 (Core Profile) Mesa 22.3.6".
  std::string description() const;
  bool debug() const { return debugEnabled_; }
  /// Whether OpenGL runs on the CPU (Mesa's llvmpipe or softpipe): multisampling is costly there.
  bool softwareRenderer() const;
  /// Throws vplab::Error naming `where` and every GL error reported since the last check
  /// (glGetError and, in debug contexts, KHR_debug messages).
  void checkErrors(std::string_view where);
  /// Reads off every GL error reported since the last check without reporting it: the ones of
  /// deleting the names a lost context took with it (WebGL), which say nothing about what follows.
  void discardErrors();

 protected:
  GlContext() = default;
  /// Loads the GL functions through `load` and, when `debug`, turns on KHR_debug output.
  void loadGl(GLADloadfunc load, bool debug, std::string_view backendName);

 private:
  GladGLContext gl_{};
  bool debugEnabled_ = false;
  std::unique_ptr<GlDebugLog> debugLog_ = std::make_unique<GlDebugLog>();  // stable address for the callback
};

/// A headless context: EGL surfaceless, OSMesa, or (automatic) EGL then OSMesa. When none can be
/// made, throws vplab::Error saying which backends were tried and why each failed.
std::unique_ptr<GlContext> createHeadlessContext(Backend backend, bool debug);

// One factory per backend file; each throws vplab::Error with the reason it failed.
std::unique_ptr<GlContext> createEglContext(bool debug);
/// An OpenGL ES 3.0 context on EGL surfaceless (the API WebGL2 follows): the shaders are checked
/// as GLSL ES 3.00 on it, and the GL backend's ES path runs on it.
std::unique_ptr<GlContext> createEglEsContext(bool debug);
std::unique_ptr<GlContext> createOsMesaContext(bool debug);

}  // namespace vplab
