// Links (app/document/url_state.h): what is shown, as the page's address says it (a bundled scene or
// lesson and its step, the camera, the views' styles and observers, the clipping strategy), and
// showing what an address says. Part of the session (app/session/session.h).
#pragma once

#include "app/document/url_state.h"
#include "app/session/viewer_model.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <utility>

namespace vplab {

class Session;

class Links {
 public:
  Links(ViewerModel& state, Session& session) : state_(state), session_(session) {}

  /// What is shown, for a link.
  UrlState urlState() const;
  /// Shows a link's state. A named bundled scene starts a new document with the link's camera (at
  /// start, or asking first when changes would be lost); a camera alone is an edit of the open
  /// scene (undoable). What cannot be used (the link's problems, a scene or lesson vplab does not
  /// bundle, a step the lesson does not have, a camera that is not valid) is left out, the rest
  /// shown, and every part left out is named at once (ViewerModel::linkProblems, the status line).
  void showUrlState(const UrlState& link, bool atStart);
  /// The views' part of a link: each view's style and observer, the clipping strategy.
  UrlState views() const;
  /// Shows what a link gives of the views; the others stay.
  void applyViews(const UrlState& link);

  /// A link naming another bundled scene while the page's worker reads it: its camera and views
  /// apply once the scene is there (Session::beginFrame).
  struct Pending {
    UrlState link;
    std::function<void()> showViews;
  };
  std::optional<Pending> takePending() { return std::exchange(pending_, std::nullopt); }
  /// `base` with the link's camera parts, or `base` (a problem added) when they make no valid camera.
  Camera cameraOver(const CameraLink& link, const Camera& base, std::vector<LinkProblem>& problems) const;
  /// Names every part of a link left out, over the views and in the status line (empty: none).
  void say(const std::vector<LinkProblem>& problems);
  void forgetPending() { pending_.reset(); }

 private:
  Language language() const { return state_.display.language; }
  void show(const UrlState& link, bool atStart, std::vector<LinkProblem>& problems);
  void showLesson(const std::filesystem::path& file, size_t linkStep, std::vector<LinkProblem>& problems);
  std::optional<std::filesystem::path> bundledPreset(const std::string& name) const;

  ViewerModel& state_;
  Session& session_;
  std::optional<Pending> pending_;
  bool showing_ = false;  // within showUrlState
};

}  // namespace vplab
