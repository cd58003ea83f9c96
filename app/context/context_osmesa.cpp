// OSMesa: Mesa's off-screen renderer, the headless fallback when EGL is not available. It renders
// into a client buffer; vplab only gives it a 1 × 1 one and draws into framebuffer objects.
#include "app/context/context.h"

#include "base/error.h"

#include <GL/osmesa.h>  // after glad/gl.h, which keeps GL/gl.h out

#include <array>

namespace vplab {

namespace {

class OsMesaContext final : public GlContext {
 public:
  explicit OsMesaContext(bool debug) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                           OSMESA_DEPTH_BITS, 24,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3,
                           OSMESA_CONTEXT_MINOR_VERSION, 3,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context_) throw Error("OSMesaCreateContextAttribs(OpenGL 3.3 core) failed");
    makeCurrent();
    loadGl(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress), debug, "osmesa");
  }

  ~OsMesaContext() override { OSMesaDestroyContext(context_); }

  std::string_view backend() const override { return "osmesa"; }

  void makeCurrent() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw Error("OSMesaMakeCurrent failed");
  }

 private:
  OSMesaContext context_ = nullptr;
  std::array<unsigned char, 4> buffer_{};
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext(bool debug) { return std::make_unique<OsMesaContext>(debug); }

}  // namespace vplab
