#include "app/session/links.h"

#include "app/lessons/lesson.h"
#include "app/session/session.h"
#include "app/text/catalogue.h"
#include "base/error.h"
#include "io/scene_io.h"

#include <algorithm>

namespace vplab {

UrlState Links::urlState() const {
  // An exercise is the whole state: the link names it (what was typed is kept per exercise).
  if (state_.practice) {
    UrlState u;
    u.embed = state_.embedViews;
    u.exercise = state_.practice->ref;
    if (state_.practice->reveal != Reveal::stages) u.reveal = state_.practice->reveal;
    return u;
  }
  // A bundled lesson's step is the whole state: the link names the lesson and the step.
  if (state_.lesson) {
    const std::filesystem::path& file = state_.lesson->lesson().file;
    const std::string name = file.stem().string();  // "02-view-orientation.en"
    std::error_code ec;
    const std::filesystem::path bundled = bundledLessonFile(name, state_.display.language);
    if (!bundled.empty() && std::filesystem::equivalent(bundled, file, ec)) {
      UrlState u;
      u.embed = state_.embedViews;
      u.lesson = name;
      u.step = state_.lesson->step() + 1;
      return u;
    }
  }
  UrlState u = views();
  u.embed = state_.embedViews;
  // The built-in scene is the bundled default.json (the same dump): a link names it as "default".
  if (state_.doc.path().empty()) u.scene = "default";
  else if (session_.files().isBundled(state_.doc.path())) u.scene = state_.doc.path().stem().string();
  u.camera = cameraLinkOf(state_.doc.scene().camera);
  return u;
}

UrlState Links::views() const {
  UrlState u;
  u.cameraStyle = state_.display.camera.style;
  u.worldStyle = state_.display.world.style;
  u.npcStyle = state_.display.npc.style;
  u.worldOrbit = state_.display.world.orbit;
  u.npcOrbit = state_.display.npc.orbit;
  u.strategy = state_.pipeline.strategy;
  return u;
}

void Links::applyViews(const UrlState& link) {
  if (link.cameraStyle) state_.display.camera.style = *link.cameraStyle;
  if (link.worldStyle) state_.display.world.style = *link.worldStyle;
  if (link.npcStyle) state_.display.npc.style = *link.npcStyle;
  if (link.worldOrbit) state_.display.world.orbit = *link.worldOrbit;
  if (link.npcOrbit) state_.display.npc.orbit = *link.npcOrbit;
  if (link.strategy) state_.pipeline.strategy = *link.strategy;
}

void Links::showUrlState(const UrlState& link, bool atStart) {
  if (link.embed != state_.embedViews) {
    state_.embedViews = link.embed;
    session_.hooks().changed();
  }
  if (link.exercise) {
    const Reveal reveal = link.reveal.value_or(Reveal::stages);
    ExerciseRef ref = *link.exercise;
    ref.language = state_.display.language;
    const bool shown = state_.practice && state_.practice->ref.spec == ref.spec && state_.practice->ref.studentId == ref.studentId &&
                       state_.practice->reveal == reveal;
    if (!shown) session_.exercises().open(ref, reveal);
    return;
  }
  if (!link.lesson.empty()) {
    const std::filesystem::path file = bundledLessonFile(link.lesson, state_.display.language);
    if (file.empty()) throw Error(text::fill(language(), "the link's lesson \"{1}\" is not one of vplab's bundled lessons", {link.lesson}));
    const size_t step = link.step > 0 ? link.step - 1 : 0;
    std::error_code ec;
    if (state_.lesson && std::filesystem::equivalent(state_.lesson->lesson().file, file, ec)) {
      if (step >= state_.lesson->stepCount())
        throw Error(text::fill(language(), "the link's step {1} is not one of the lesson's {2} steps",
                           {std::to_string(link.step), std::to_string(state_.lesson->stepCount())}));
      session_.hooks().goToStep(step);  // the address followed a step: move there
      session_.hooks().changed();
      return;
    }
    session_.openLesson(file, step);
    return;
  }
  auto showViews = [this, link] {
    applyViews(link);
    session_.hooks().changed();
  };
  const bool otherScene = !link.scene.empty() && link.scene != urlState().scene;
  if (otherScene || (atStart && !link.camera.empty())) {
    Scene scene = state_.doc.scene();
    if (otherScene) {
      const auto preset = std::find_if(session_.files().presets().begin(), session_.files().presets().end(),
                                       [&](const SceneFileInfo& p) { return p.file.stem() == link.scene; });
      if (preset == session_.files().presets().end()) throw Error(text::fill(language(), "the link's scene \"{1}\" is not one of vplab's bundled scenes", {link.scene}));
      if (session_.loader().remote()) {
        // The page: its worker reads the scene while the page goes on (a million triangles took most
        // of a second); the link's camera and views apply when it is there (beginFrame).
        session_.unlessUnsaved([this, file = preset->file, link, showViews] {
          session_.loader().start(file);
          pending_ = Pending{link, showViews};
          session_.hooks().changed();
        });
        return;
      }
      scene = loadScene(preset->file);
    }
    scene.camera = link.camera.over(scene.camera);
    session_.unlessUnsaved([this, scene = std::move(scene), showViews]() mutable {
      session_.startDocument(std::move(scene));
      showViews();
    });
    return;
  }
  if (const Camera c = link.camera.over(state_.doc.scene().camera); c != state_.doc.scene().camera) state_.doc.scene().camera = c;
  showViews();
}

}  // namespace vplab
