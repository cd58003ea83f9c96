// Fuzz target: a scene file (JSON) as `vplab dump --scene` reads it, then the whole pipeline.
// Mesh files are resolved relative to assets/scenes, so "../meshes/house.obj" is found.
#include "base/error.h"
#include "io/scene_io.h"
#include "tests/fuzz/fuzz_run.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace vplab;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const Scene scene = parseScene(text, "fuzz.json", VPLAB_ASSETS "/scenes", fuzz::fuzzLimits());
    fuzz::runEverything(scene);
  } catch (const Error&) {
    // a clear user error is the right answer to a bad file; anything else escapes and is a finding
  }
  return 0;
}
