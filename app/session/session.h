// The document's life beyond editing (docs/lecturers.md "The viewer"), without ImGui or GL (issue 39
// item 1): a new document, a scene read on a worker thread (with progress and Cancel) or an OBJ added,
// a lesson opened, and asking before unsaved changes are lost or the program quits. What it asks the
// user is state here (a question and its answers); the dialogs that show the questions are
// app/ui/session_dialogs.h, and tests/app/session/ drive the answers without a window. Its parts:
//   SceneFiles   open, save, never over a bundled scene (app/session/scene_files.h)
//   Recoveries   autosave and recovery (app/session/recoveries.h)
//   Links        the page's address, both ways (app/session/links.h)
//   Exercises    an exercise practised beside the views: open, Check, keep, Hand in (app/session/exercises.h)
#pragma once

#include "app/document/loader.h"
#include "app/lessons/lesson.h"
#include "app/session/exercises.h"
#include "app/session/file_chooser.h"
#include "app/session/links.h"
#include "app/session/recoveries.h"
#include "app/session/scene_files.h"
#include "app/session/viewer_model.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vplab {

class Session {
 public:
  /// What the session asks of the viewer: `changed` after something the frame shows changed (a new
  /// document, a link, a load started or cancelled: the viewer runs the pipeline if its input changed
  /// and asks for frames); `goToStep` moves the open lesson to a step (from 0), as its keys do.
  struct Hooks {
    std::function<void()> changed = [] {};
    std::function<void(size_t step)> goToStep = [](size_t) {};
  };
  /// Works on `state` (its document, the views' choices, the lecture, the status); asks for files
  /// through `chooser` (the desktop's dialog, the page's picker).
  Session(ViewerModel& state, std::unique_ptr<FileChooser> chooser, Hooks hooks);
  Session(const Session&) = delete;  // its parts hold references to it
  Session& operator=(const Session&) = delete;

  SceneFiles& files() { return files_; }
  Recoveries& recovery() { return recovery_; }
  Links& links() { return links_; }
  Exercises& exercises() { return exercises_; }
  SceneLoader& loader() { return loader_; }

  // ------------------------------------------------------------ documents
  /// New: the default lecture scene, asking first when changes would be lost.
  void newDocument();
  /// Opens a scene file on a worker thread (File > Open, presets); the views keep drawing the open
  /// scene, with a progress bar and Cancel, until it has loaded.
  void openScene(const std::filesystem::path& file);
  /// Cancel of the loading bar.
  void cancelLoading();
  /// A new document (opened, preset, New, recovered): clean unless recovered, no undo history, and
  /// the view settings of a fresh start (a style chosen for the old scene, e.g. hidden-line, may be
  /// far too slow for the new one; docs/lecturers.md "The viewer").
  void startDocument(Scene scene, bool dirty = false);
  /// Opens a lesson (docs/lecturers.md "Lessons") at `step` (from 0), asking first when changes would be
  /// lost: its first step's scene becomes a new document and the caption box shows the step. A lesson
  /// that cannot be read leaves everything as it was and says why in the status line. A step beyond
  /// the lesson's last is its last; with `beyond`, the first, and `beyond` is told the lesson's step
  /// count (a link that names a step the lesson does not have says so).
  void openLesson(const std::filesystem::path& file, size_t step = 0, std::function<void(size_t steps)> beyond = {});
  /// The open lesson read again at its step for the world view's shape now (state().worldAspect):
  /// in the page a lesson opens from the link before the views have a shape (an embed's world view
  /// beside the camera view on a phone is five times taller than the default; PRP fell outside it).
  /// Nothing happens to a lesson whose step was changed; the status line keeps what it said.
  void reframeLesson();
  /// What a lesson's steps are resolved against: the bundled scenes and a fresh document's views.
  LessonContext lessonContext() const;

  // ------------------------------------------------------------ questions to the user
  /// Runs `action` (which replaces the scene) at once, or asks first when unsaved changes would be lost.
  void unlessUnsaved(std::function<void()> action);
  /// Whether "discard the unsaved changes?" is asked; its answers.
  bool discardAsked() const { return bool(pendingReplace_); }
  void discardChanges();
  void keepEditing() { pendingReplace_ = nullptr; }
  /// Whether "save before quitting?" is asked (a quit was requested with unsaved changes); its answers.
  /// Saving a bundled or built-in scene asks for the copy's name first, then quits once it is saved.
  bool quitAsked() const { return state_.quitRequested && state_.doc.dirty(); }
  void saveAndQuit() { files_.saveBeforeQuitting(); }
  void discardAndQuit() { state_.quitConfirmed = true; }
  void cancelQuit() { state_.quitRequested = false; }
  /// Whether a question is open (these or a recovery): nothing behind it may move.
  bool asking() const { return discardAsked() || quitAsked() || !recovery_.recoveries().empty(); }

  // ------------------------------------------------------------ each frame
  /// At the frame's start: an OBJ the scene panel asked for starts loading; a finished load arrives.
  /// Returns whether something arrived (the frame then settles again).
  bool beginFrame();
  /// At the frame's end, at time `now` (s): a quit without unsaved changes is confirmed, and the
  /// autosave writes what is due.
  void endFrame(double now);
  /// Seconds until the session needs a frame: 0 while a file loads, the next autosave, else nothing.
  std::optional<double> wakeIn(double now) const;

  // ------------------------------------------------------------ start and the language
  /// What the platform hands the session at start: the window reads it from the preferences file and
  /// the state directory (app/ui/run_viewer.cpp), the page from localStorage (app/web/page.cpp).
  struct Start {
    Language language = Language::en;
    /// How a chosen language is kept for the next start; throws vplab::Error when it cannot be.
    /// Empty: it is not kept.
    std::function<void(Language)> rememberLanguage{};
    std::vector<Recovery> recoveries{};          // unsaved changes of sessions that ended, newest first
    std::filesystem::path autosaveDirectory{};   // where this session's are kept; empty: nowhere
    AnswerShelf answers{};                       // where exercises' answers are kept; empty: nowhere
  };
  /// Starts as the platform found things: the language and how a choice is kept, the kept scenes
  /// offered, autosave after kAutosaveDelay seconds of quiet.
  void start(Start start);
  /// View > Language: the menus', panels' and views' language from the next frame on, remembered as
  /// the start said. A choice that cannot be remembered still applies, and the status line says why
  /// it is not kept.
  void chooseLanguage(Language lang);

  /// For the parts: what to tell the viewer.
  const Hooks& hooks() const { return hooks_; }

 private:
  Language language() const { return state_.display.language; }
  /// The views of a fresh start; the user's preferences (theme, labels' language) kept.
  DisplaySettings freshDisplay() const;

  ViewerModel& state_;
  Hooks hooks_;
  std::function<void(Language)> rememberLanguage_;
  std::function<void()> pendingReplace_;  // waiting for "discard the unsaved changes?"
  SceneLoader loader_;
  SceneFiles files_;
  Recoveries recovery_;
  Links links_;
  Exercises exercises_;
};

/// Adds an object of `shape` where the camera looks, selected (the scene panel's "+ cube" …). A mesh
/// (an OBJ `file`) is read on the session's worker thread: it joins the scene when loaded.
void addObject(DocumentPart& d, EditPart& e, StatusPart& status, Shape shape, std::string file = {});

}  // namespace vplab
