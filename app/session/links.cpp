#include "app/session/links.h"

#include "app/inspect/camera_text.h"
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
  std::vector<LinkProblem> problems = link.problems;
  state_.linkProblems.clear();
  showing_ = true;
  show(link, atStart, problems);
  showing_ = false;
  // A lesson opened at once has said a step it does not have already (showLesson): it comes last.
  problems.insert(problems.end(), state_.linkProblems.begin(), state_.linkProblems.end());
  say(problems);
}

void Links::say(const std::vector<LinkProblem>& problems) {
  state_.linkProblems = problems;
  if (!problems.empty())
    state_.setStatus(text::fill(language(), "Not understood in the link, and left out: {1}", {saidTogether(problems, language())}), true);
  session_.hooks().changed();
}

void Links::show(const UrlState& link, bool atStart, std::vector<LinkProblem>& problems) {
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
    if (!file.empty()) {
      if (!link.scene.empty() || !link.camera.empty())
        problems.push_back({!link.scene.empty() ? "scene" : "", "", "left out: a lesson's step brings its own scene and camera", {}});
      showLesson(file, link.step, problems);
      return;
    }
    // The rest of the link is used as if it named no lesson.
    problems.push_back({"lesson", link.lesson, "not one of vplab's bundled lessons", {}});
  }
  auto showViews = [this, link] {
    applyViews(link);
    session_.hooks().changed();
  };
  std::string scene = link.scene;
  if (!scene.empty() && !bundledPreset(scene)) {
    problems.push_back({"scene", scene, "not one of vplab's bundled scenes", {}});
    scene.clear();
  }
  const bool otherScene = !scene.empty() && scene != urlState().scene;
  if (otherScene || (atStart && !link.camera.empty())) {
    Scene shown = state_.doc.scene();
    if (otherScene) {
      const std::filesystem::path file = *bundledPreset(scene);
      if (session_.loader().remote()) {
        // The page: its worker reads the scene while the page goes on (a million triangles took most
        // of a second); the link's camera and views apply when it is there (beginFrame).
        session_.unlessUnsaved([this, file, link, showViews] {
          session_.loader().start(file);
          pending_ = Pending{link, showViews};
          session_.hooks().changed();
        });
        return;
      }
      shown = loadScene(file);
    }
    shown.camera = cameraOver(link.camera, shown.camera, problems);
    session_.unlessUnsaved([this, shown = std::move(shown), showViews]() mutable {
      session_.startDocument(std::move(shown));
      showViews();
    });
    return;
  }
  if (const Camera c = cameraOver(link.camera, state_.doc.scene().camera, problems); c != state_.doc.scene().camera)
    state_.doc.scene().camera = c;
  showViews();
}

void Links::showLesson(const std::filesystem::path& file, size_t linkStep, std::vector<LinkProblem>& problems) {
  const size_t step = linkStep > 0 ? linkStep - 1 : 0;
  std::error_code ec;
  if (state_.lesson && std::filesystem::equivalent(state_.lesson->lesson().file, file, ec)) {
    if (step >= state_.lesson->stepCount()) {  // the lesson stays where it is
      problems.push_back({"step", std::to_string(linkStep), "the lesson has {1} steps: it opens at its first",
                          std::to_string(state_.lesson->stepCount())});
      return;
    }
    session_.hooks().goToStep(step);  // the address followed a step: move there
    session_.hooks().changed();
    return;
  }
  // A step the lesson does not have opens its first, said once the lesson is read.
  session_.openLesson(file, step, [this, linkStep, problems](size_t steps) {
    const LinkProblem beyond{"step", std::to_string(linkStep), "the lesson has {1} steps: it opens at its first", std::to_string(steps)};
    if (showing_) {
      state_.linkProblems.push_back(beyond);  // showUrlState says it with the others
      return;
    }
    std::vector<LinkProblem> all = problems;  // opened later, once unsaved changes were answered for
    all.push_back(beyond);
    say(all);
  });
}

std::optional<std::filesystem::path> Links::bundledPreset(const std::string& name) const {
  const auto& presets = session_.files().presets();
  const auto preset = std::find_if(presets.begin(), presets.end(), [&](const SceneFileInfo& p) { return p.file.stem() == name; });
  if (preset == presets.end()) return std::nullopt;
  return preset->file;
}

Camera Links::cameraOver(const CameraLink& link, const Camera& base, std::vector<LinkProblem>& problems) const {
  const Camera c = link.applied(base);
  const std::optional<CameraProblem> problem = cameraProblem(c);
  if (!problem) return c;
  problems.push_back({"", "", "the camera is not valid, the scene's own is shown: {1}", cameraProblemText(*problem, c, language())});
  return base;
}

}  // namespace vplab
