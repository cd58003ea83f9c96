// An exercise opened beside the views (issue 40): from a link's keys, an exercise's folder or the
// command line (`vplab --exercise DIR`); Check; the student's answer kept per exercise as it is typed
// (it survives a closed window, a reload); Hand in (answer.json, as `vplab grade batch` reads it). Part
// of the session (app/session/session.h), through which the exercise's scene becomes the document.
#pragma once

#include "app/session/viewer_model.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace vplab {

class Session;

/// Where a student's answers are kept between sessions, one per exercise (exerciseKey): files in the
/// state directory on the desktop, localStorage in the browser. Empty functions: nowhere.
struct AnswerShelf {
  std::function<std::optional<std::string>(const std::string& key)> load;
  /// Returns false when it could not be kept (the disk or the browser's storage full).
  std::function<bool(const std::string& key, const std::string& text)> store;
  /// The shelf of files `directory`/KEY.json (written atomically).
  static AnswerShelf inDirectory(const std::filesystem::path& directory);
};

class Exercises {
 public:
  Exercises(ViewerModel& state, Session& session) : state_(state), session_(session) {}

  /// The exercise `ref` names (a link's `#exercise=…`), asking first when changes to the scene would
  /// be lost; its kept answer fills the fields. False (the reason in the status line) when there is none.
  bool open(const ExerciseRef& ref, Reveal reveal);
  /// An exercise's folder written by `vplab exercise` (File ▸ Open exercise…, `--exercise DIR`): the
  /// answer kept of it, else the folder's answer.json, fills the fields.
  bool openFolder(const std::filesystem::path& dir, Reveal reveal);
  /// An exercise's exercise.json, or an answer.json that names its exercise, its values in the fields
  /// (app/practice/practice.h openPracticeFile). False, the reason in the status line, for any other.
  bool openFile(const std::filesystem::path& file, Reveal reveal);
  /// File ▸ Open exercise…: the chooser, for a folder's exercise.json or an answer.json (in the
  /// browser, the file a course gave or one handed in before).
  void chooseFile(Reveal reveal = Reveal::stages);
  /// Ends practising; the scene stays.
  void close();

  /// Check: grades the fields as `vplab grade numbers` does; the panel and the views show it.
  void check();
  /// Hand in: answer.json through the file chooser (the exercise's folder suggested; the browser
  /// downloads it).
  void handIn();
  /// Writes the answer file of the fields to `file` (atomically). Throws vplab::Error.
  void writeAnswer(const std::filesystem::path& file) const;

  /// Where answers are kept (Session::Start); the open exercise's answer is kept from then on.
  void keepOn(AnswerShelf shelf) { shelf_ = std::move(shelf); }
  /// At the frame's end: the fields' answer is kept when it changed.
  void endFrame();

 private:
  Language language() const { return state_.display.language; }
  /// Starts the exercise `make` gives; false, the reason in the status line, when it throws.
  bool startMade(const std::function<Practice()>& make);
  /// The exercise becomes the document (asked first when changes would be lost) and its answer kept is restored.
  void start(std::shared_ptr<Practice> practice);

  ViewerModel& state_;
  Session& session_;
  AnswerShelf shelf_;
  std::string keepError_;  // the last failure to keep the answer, said once
};

/// The student's numbers for the views (app/practice/practice_marks.h): the pass the step-through
/// shows, their matrices read as the last Check read them (the row-vector form transposed).
Highlights::Student studentMarks(const PracticePart& practice, const StepThrough& stepThrough);

}  // namespace vplab
