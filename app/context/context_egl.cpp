// EGL surfaceless (EGL_MESA_platform_surfaceless): a GL context with no window and no default
// framebuffer; everything renders into framebuffer objects. libEGL is opened at run time by GLAD's
// loader, so a machine without it gets an error message, not a failure to start.
#include "app/context/context.h"

#include "base/error.h"

#include <glad/egl.h>

namespace vplab {

namespace {

std::string eglErrorName(EGLint e) {
  switch (e) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error " + std::to_string(e);
  }
}

class EglContext final : public GlContext {
 public:
  /// `share`: the context whose objects the new one shares (EGL_NO_CONTEXT: none). `es`: OpenGL ES
  /// 3.0 (the API WebGL2 follows) instead of desktop OpenGL 3.3 core.
  explicit EglContext(bool debug, EGLContext share = EGL_NO_CONTEXT, bool es = false) : es_(es) {
    if (!gladLoaderLoadEGL(EGL_NO_DISPLAY)) throw Error("libEGL.so.1 could not be loaded");
    if (!GLAD_EGL_EXT_platform_base || !GLAD_EGL_MESA_platform_surfaceless)
      throw Error("EGL_MESA_platform_surfaceless is not supported by this EGL");
    display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display_ == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT(surfaceless)");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) fail("eglInitialize");
    gladLoaderLoadEGL(display_);  // again, now that the display's extensions are known
    if (!GLAD_EGL_KHR_surfaceless_context) throw Error("EGL_KHR_surfaceless_context is not supported");
    bindApi();
    // No window, so no window config: a pbuffer-capable one, or none at all (KHR_no_config_context).
    const EGLint renderable = es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT;
    const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, renderable, EGL_NONE};
    EGLConfig config = EGL_NO_CONFIG_KHR;
    EGLint count = 0;
    if ((!eglChooseConfig(display_, configAttribs, &config, 1, &count) || count < 1) &&
        !GLAD_EGL_KHR_no_config_context)
      fail(es ? "eglChooseConfig(EGL_OPENGL_ES3_BIT)" : "eglChooseConfig(EGL_OPENGL_BIT)");
    if (count < 1) config = EGL_NO_CONFIG_KHR;
    const EGLint glAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                                EGL_CONTEXT_MINOR_VERSION, 3,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
                                EGL_NONE};
    const EGLint esAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3,
                                EGL_CONTEXT_MINOR_VERSION, 0,
                                EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
                                EGL_NONE};
    context_ = eglCreateContext(display_, config, share, es ? esAttribs : glAttribs);
    if (context_ == EGL_NO_CONTEXT) fail(es ? "eglCreateContext(OpenGL ES 3.0)" : "eglCreateContext(OpenGL 3.3 core)");
    makeCurrent();
    loadGl(reinterpret_cast<GLADloadfunc>(eglGetProcAddress), debug, es ? "egl (OpenGL ES)" : "egl");
  }

  // The display is not terminated: EGL hands every context of the process the same surfaceless
  // display, and eglTerminate would pull it from under the other contexts still alive.
  ~EglContext() override {
    if (context_ != EGL_NO_CONTEXT) {
      // A shared context may end on a thread where another context is current: leave that one be.
      eglBindAPI(es_ ? EGL_OPENGL_ES_API : EGL_OPENGL_API);
      if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display_, context_);
    }
  }

  std::string_view backend() const override { return "egl"; }

  std::unique_ptr<GlContext> createShared() override {
    auto shared = std::make_unique<EglContext>(debug(), context_, es_);
    makeCurrent();  // the new context's constructor made itself current
    return shared;
  }
  void releaseCurrent() override {
    bindApi();
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }

  void makeCurrent() override {
    bindApi();  // EGL keeps a current context per API and thread: the calls below act on this one's
    // Mesa's EGL skips a context it believes current, but OSMesa shares Mesa's dispatch (libglapi)
    // and may have taken it since (issue 39: a process that used both drew with OSMesa's context):
    // released first, the context is bound again for certain.
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("eglMakeCurrent");
  }

 private:
  void bindApi() {
    if (!eglBindAPI(es_ ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
      fail(es_ ? "eglBindAPI(EGL_OPENGL_ES_API)" : "eglBindAPI(EGL_OPENGL_API)");
  }

  [[noreturn]] void fail(const char* call) {
    const EGLint e = eglGetError();
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    context_ = EGL_NO_CONTEXT;
    throw Error(std::string(call) + " failed: " + eglErrorName(e));
  }

  bool es_ = false;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlContext> createEglContext(bool debug) { return std::make_unique<EglContext>(debug); }

std::unique_ptr<GlContext> createEglEsContext(bool debug) {
  return std::make_unique<EglContext>(debug, EGL_NO_CONTEXT, /*es=*/true);
}

}  // namespace vplab
