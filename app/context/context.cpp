#include "app/context/context.h"

#include "base/error.h"

namespace vplab {

namespace {

void GLAD_API_PTR onDebugMessage(GLenum source, GLenum type, GLuint /*id*/, GLenum severity,
                                 GLsizei length, const GLchar* message, const void* user) {
  if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
  // Mesa also sends compile and link logs this way; gl::Program reports those itself.
  if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
  auto* log = static_cast<GlDebugLog*>(const_cast<void*>(user));
  log->errors.emplace_back(message, length > 0 ? size_t(length) : std::char_traits<char>::length(message));
}

std::string glErrorName(GLenum e) {
  switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case 0x9242: return "CONTEXT_LOST_WEBGL (the browser took the WebGL context away)";
    default: return "GL error " + std::to_string(e);
  }
}

/// GLAD loads desktop GL's functions by the version the context reports, so on OpenGL ES 3.x it
/// leaves out the ones desktop GL got in 3.1 – 3.3 that ES 3.0 has too (instancing, sync objects):
/// loaded here by name.
void loadEsCoreFunctions(GladGLContext& gl, GLADloadfunc load) {
#define VPLAB_LOAD(name, type) \
  if (!gl.name) gl.name = reinterpret_cast<type>(load("gl" #name))
  VPLAB_LOAD(DrawArraysInstanced, PFNGLDRAWARRAYSINSTANCEDPROC);
  VPLAB_LOAD(DrawElementsInstanced, PFNGLDRAWELEMENTSINSTANCEDPROC);
  VPLAB_LOAD(VertexAttribDivisor, PFNGLVERTEXATTRIBDIVISORPROC);
  VPLAB_LOAD(FenceSync, PFNGLFENCESYNCPROC);
  VPLAB_LOAD(ClientWaitSync, PFNGLCLIENTWAITSYNCPROC);
  VPLAB_LOAD(DeleteSync, PFNGLDELETESYNCPROC);
  VPLAB_LOAD(GetSynciv, PFNGLGETSYNCIVPROC);
  VPLAB_LOAD(GetInteger64v, PFNGLGETINTEGER64VPROC);
  VPLAB_LOAD(CopyBufferSubData, PFNGLCOPYBUFFERSUBDATAPROC);
#undef VPLAB_LOAD
}

}  // namespace

void GlContext::loadGl(GLADloadfunc load, bool debug, std::string_view backendName) {
  const int version = gladLoadGLContext(&gl_, load);
  if (version == 0) throw Error(std::string(backendName) + ": loading the OpenGL functions failed");
  const auto* versionText = reinterpret_cast<const char*>(gl_.GetString(GL_VERSION));
  const bool es = versionText && std::string_view(versionText).starts_with("OpenGL ES");
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < (es ? 30 : 33))
    throw Error(std::string(backendName) + (es ? ": OpenGL ES 3.0" : ": OpenGL 3.3 core") + " is needed, the context has " +
                std::to_string(GLAD_VERSION_MAJOR(version)) + "." + std::to_string(GLAD_VERSION_MINOR(version)));
  if (es) loadEsCoreFunctions(gl_, load);
  if (debug) {
    if (!gl_.KHR_debug) throw Error(std::string(backendName) + ": GL_KHR_debug is not available for a debug context");
    gl_.Enable(GL_DEBUG_OUTPUT);
    gl_.Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    gl_.DebugMessageCallback(onDebugMessage, debugLog_.get());
    debugEnabled_ = true;
  }
}

std::string GlContext::description() const {
  auto str = [&](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(gl_.GetString(name));
    return std::string(s ? s : "?");
  };
  return str(GL_RENDERER) + " — " + str(GL_VERSION);
}

bool GlContext::softwareRenderer() const {
  const auto* r = reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER));
  const std::string renderer = r ? r : "";
  return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

void GlContext::checkErrors(std::string_view where) {
  std::string problems;
  for (GLenum e = gl_.GetError(); e != GL_NO_ERROR; e = gl_.GetError()) problems += "\n  " + glErrorName(e);
  for (const std::string& m : debugLog_->errors) problems += "\n  KHR_debug: " + m;
  debugLog_->errors.clear();
  if (!problems.empty()) throw Error("OpenGL error while " + std::string(where) + ":" + problems);
}

void GlContext::discardErrors() {
  for (int i = 0; i < 64 && gl_.GetError() != GL_NO_ERROR; ++i) {
  }
  debugLog_->errors.clear();
}

std::unique_ptr<GlContext> createHeadlessContext(Backend backend, bool debug) {
  if (backend == Backend::egl) return createEglContext(debug);
  if (backend == Backend::osmesa) return createOsMesaContext(debug);
  std::string reasons;
  try {
    return createEglContext(debug);
  } catch (const Error& e) {
    reasons += "\n  egl: " + std::string(e.what());
  }
  try {
    return createOsMesaContext(debug);
  } catch (const Error& e) {
    reasons += "\n  osmesa: " + std::string(e.what());
  }
  throw Error("no OpenGL 3.3 context could be made; tried:" + reasons);
}

}  // namespace vplab
