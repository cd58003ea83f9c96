// Fuzz target: a lesson file (JSON) as `vplab --lesson` reads it (app/lessons/lesson.h), then every
// step's scene through the pipeline and every move between two steps, which must show valid cameras
// only (an invalid one is a finding: the move's promise, app/lessons/lesson_transition.h).
#include "app/lessons/lesson.h"
#include "app/lessons/lesson_transition.h"
#include "base/error.h"
#include "tests/fuzz/fuzz_run.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace vplab;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  LessonContext context;
  context.scenesDirectory = VPLAB_ASSETS "/scenes";
  context.limits = fuzz::fuzzLimits();
  context.lessonLimits.steps = 40;  // one input in milliseconds: what exceeds it is refused first
  try {
    const Lesson lesson = parseLesson(text, "fuzz.json", VPLAB_ASSETS "/lessons", context);
    for (size_t i = 0; i < lesson.steps.size(); ++i) {
      fuzz::runEverything(lesson.steps[i].state.scene);
      if (i == 0) continue;
      for (double t : {0.1, 0.5, 0.9})
        if (cameraError(stateBetween(lesson.steps[i - 1].state, lesson.steps[i].state, t).scene.camera)) std::abort();
    }
  } catch (const Error&) {
    // a clear user error is the right answer to a bad file; anything else escapes and is a finding
  }
  return 0;
}
