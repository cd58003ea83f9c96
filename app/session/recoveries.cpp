#include "app/session/recoveries.h"

#include "app/lessons/lesson.h"
#include "app/session/session.h"
#include "app/text/catalogue.h"
#include "base/error.h"

namespace vplab {

void Recoveries::enableAutosave(const std::filesystem::path& directory, double delaySeconds) {
  autosave_ = std::make_unique<Autosave>(directory, delaySeconds);
}

std::filesystem::path Recoveries::writeRecoveryNow() {
  if (!autosave_ || !autosave_->writeNow(state_.doc, recoveryView())) return {};
  return autosave_->file();
}

void Recoveries::endSession() {
  if (autosave_) autosave_->removeFile();
}

void Recoveries::offerRecoveries(std::vector<Recovery> recoveries) {
  recoveries_ = std::move(recoveries);
}

std::string Recoveries::sceneName(const Recovery& r) const {
  return r.scenePath.empty() ? text::Text("the default lecture scene").in(language()) : r.scenePath.string();
}

RecoveryView Recoveries::recoveryView() const {
  RecoveryView v;
  if (state_.lesson) {
    v.lesson = state_.lesson->lesson().file;
    v.step = state_.lesson->step();
  }
  v.views = encodeUrlState(session_.links().views());
  return v;
}

void Recoveries::showRecoveredView(const RecoveryView& v) {
  // The lesson at its step, as it was left: settled (its step's state is not applied again over
  // the recovered scene). A lesson that cannot be read any more leaves the scene alone.
  if (!v.lesson.empty()) {
    try {
      Lesson lesson = loadLesson(v.lesson, session_.lessonContext());
      const size_t step = std::min(v.step, lesson.steps.size() - 1);
      state_.lesson.emplace(std::move(lesson), step);
      state_.lesson->markSettled();
    } catch (const Error& e) {
      state_.setStatus(e.what(), true);
    }
  }
  try {
    session_.links().applyViews(decodeUrlState(v.views));
  } catch (const Error&) {
    // the views of a fresh start
  }
  // The camera in the fields as it was typed; the views keep the scene's, the last valid one.
  if (v.editedCamera) state_.doc.scene().camera = *v.editedCamera;
  // And the objects' transforms as typed (an index beyond the scene is someone else's file: ignored).
  for (const auto& [index, transform] : v.editedTransforms)
    if (index < state_.doc.scene().objects.size()) state_.doc.scene().objects[index].transform = transform;
  if (v.editedCamera || !v.editedTransforms.empty()) state_.doc.endFrame(false);
}

void Recoveries::recover(size_t i) {
  if (i >= recoveries_.size()) return;
  const Recovery r = recoveries_[i];
  try {
    session_.startDocument(Autosave::load(r), /*dirty=*/true);
    showRecoveredView(Autosave::loadView(r));
    Autosave::discard(r);  // this session's autosave keeps them from now on
    if (autosave_) autosave_->writeNow(state_.doc, recoveryView());
    const size_t others = recoveries_.size() - 1;
    const std::string name = sceneName(r), count = std::to_string(others);
    if (others == 0) state_.setStatus(text::fill(language(), "recovered the unsaved changes of {1}", {name}), false);
    else if (others == 1 && session_.files().browser())
      state_.setStatus(text::fill(language(), "recovered the unsaved changes of {1}; 1 other kept scene is offered in the next tab or visit", {name}), false);
    else if (others == 1)
      state_.setStatus(text::fill(language(), "recovered the unsaved changes of {1}; 1 other kept scene is offered at the next start", {name}), false);
    else if (session_.files().browser())
      state_.setStatus(text::fill(language(), "recovered the unsaved changes of {1}; {2} other kept scenes are offered in the next tab or visit", {name, count}), false);
    else
      state_.setStatus(text::fill(language(), "recovered the unsaved changes of {1}; {2} other kept scenes are offered at the next start", {name, count}), false);
  } catch (const Error& e) {
    state_.setStatus(e.what(), true);  // the file stays for another try
  }
  recoveries_.clear();
}

void Recoveries::discardRecovery(size_t i) {
  if (i >= recoveries_.size()) return;
  Autosave::discard(recoveries_[i]);
  recoveries_.erase(recoveries_.begin() + std::ptrdiff_t(i));
}

void Recoveries::recoverLater() {
  recoveries_.clear();  // all stay kept
  state_.setStatus(session_.files().browser() ? text::Text("the kept scenes are offered again in the next tab or visit").in(language())
                     : text::Text("the kept scenes are offered again at the next start").in(language()),
            false);
}

void Recoveries::endFrame(double now) {
  if (!autosave_) return;
  // What else is on screen matters only to a file that will be written: not built every clean frame.
  if (state_.doc.dirty()) autosave_->update(state_.doc, now, recoveryView());
  else autosave_->update(state_.doc, now);
  if (autosave_->error() != autosaveError_) {  // say it once, not every frame
    autosaveError_ = autosave_->error();
    if (!autosaveError_.empty()) state_.setStatus(autosaveError_, true);
  }
}

std::optional<double> Recoveries::dueIn(double now) const {
  if (autosave_) return autosave_->dueIn(now);
  return std::nullopt;
}

}  // namespace vplab
