// Fuzz target: an OBJ file as a scene's mesh object reads it, then the whole pipeline, with the
// default lecture scene's camera looking at it.
#include "base/error.h"
#include "io/obj_mesh.h"
#include "tests/fuzz/fuzz_run.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace vplab;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  static const Scene lecture = [] {  // the camera and lights; the one object is replaced
    Scene s = defaultScene();
    s.objects.resize(1);
    s.objects[0].shape = Shape::mesh;
    s.objects[0].file = "fuzz.obj";
    return s;
  }();
  try {
    Scene scene = lecture;
    scene.objects[0].mesh = std::make_shared<Mesh>(parseObj(text, "fuzz.obj", fuzz::fuzzLimits()));
    fuzz::runEverything(scene);
  } catch (const Error&) {
    // a clear user error is the right answer to a bad file; anything else escapes and is a finding
  }
  return 0;
}
