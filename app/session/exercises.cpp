#include "app/session/exercises.h"

#include "app/document/atomic_file.h"
#include "app/practice/practice_marks.h"
#include "app/session/session.h"
#include "app/text/catalogue.h"
#include "base/error.h"
#include "io/limits.h"
#include "io/read_file.h"

#include <memory>

namespace vplab {

AnswerShelf AnswerShelf::inDirectory(const std::filesystem::path& directory) {
  AnswerShelf shelf;
  shelf.load = [directory](const std::string& key) -> std::optional<std::string> {
    std::error_code ec;
    const std::filesystem::path file = directory / (key + ".json");
    if (!std::filesystem::exists(file, ec)) return std::nullopt;
    try {
      return readRegularFile(file, kDefaultLimits.sceneFileBytes, "kept answer");
    } catch (const Error&) {
      return std::nullopt;  // a kept answer that cannot be read is as if none were kept
    }
  };
  shelf.store = [directory](const std::string& key, const std::string& text) {
    try {
      std::error_code ec;
      std::filesystem::create_directories(directory, ec);
      writeFileAtomically(directory / (key + ".json"), text);
      return true;
    } catch (const Error&) {
      return false;
    }
  };
  return shelf;
}

bool Exercises::open(const ExerciseRef& ref, Reveal reveal) {
  return startMade([&] { return openPractice(ref, reveal, language()); });
}

bool Exercises::openFolder(const std::filesystem::path& dir, Reveal reveal) {
  return startMade([&] { return openPracticeFolder(dir, reveal, language()); });
}

bool Exercises::startMade(const std::function<Practice()>& make) {
  try {
    start(std::make_shared<Practice>(make()));
    return true;
  } catch (const Error& e) {
    state_.setStatus(text::fill(language(), "the exercise could not be opened: {1}", {e.what()}), true);
    return false;
  }
}

bool Exercises::openFile(const std::filesystem::path& file, Reveal reveal) {
  return startMade([&] { return openPracticeFile(file, reveal, language()); });
}

void Exercises::chooseFile(Reveal reveal) {
  session_.files().fileDialog().open(text::Text("Open an exercise: its exercise.json, or an answer.json").in(language()),
                                     FileChooser::Mode::open, {".json"}, {},
                                     [this, reveal](const std::filesystem::path& file) { openFile(file, reveal); });
}

void Exercises::start(std::shared_ptr<Practice> practice) {
  session_.unlessUnsaved([this, practice] {
    session_.startDocument(practice->exercise.scene);
    // The sheets name the polygon's vertices P1 … Pn: so do the views. A clipping sheet steps
    // through the polygon's passes (the Lecture tab's step-through), the student's beside the lab's.
    state_.display.overlays.vertexNames = true;
    if (exerciseShows(practice->ref.spec.topic, ExerciseTopic::clipping)) state_.stepThrough = {true, 0, 0, 0};
    // What the student typed before (this exercise's kept answer) comes back; a new one keeps the
    // folder's. An answer.json the student opened is what they asked to see.
    if (shelf_.load && !practice->answerOpened)
      if (const auto kept = shelf_.load(exerciseKey(practice->ref))) {
        try {
          fillFields(practice->fields, parseAnswer(*kept, "kept answer"));
        } catch (const Error&) {
          // a kept answer that cannot be read is as if none were kept
        }
      }
    state_.practice = std::move(*practice);
    state_.keptEdits = state_.practice->edits;
    state_.check.reset();
    state_.showTasks = true;
    state_.focusFirstField = true;
    state_.setStatus(text::fill(language(), "opened the exercise {1}", {exerciseKey(state_.practice->ref)}), false);
    session_.hooks().changed();
  });
}

void Exercises::close() {
  endFrame();  // what was typed last is kept
  state_.practice.reset();
  state_.check.reset();
  session_.hooks().changed();
}

void Exercises::check() {
  if (!state_.practice) return;
  setPracticeLanguage(*state_.practice, language());
  state_.check = checkPractice(*state_.practice, language());
  session_.hooks().changed();
}

void Exercises::writeAnswer(const std::filesystem::path& file) const {
  if (!state_.practice) throw Error("no exercise is open");
  writeFileAtomically(file, practiceAnswer(*state_.practice).dump(2) + "\n");
}

void Exercises::handIn() {
  if (!state_.practice) return;
  const std::filesystem::path start = state_.practice->folder.empty() ? std::filesystem::path("answer.json")
                                                                      : state_.practice->folder / "answer.json";
  session_.files().fileDialog().open(text::Text("Hand in answer.json").in(language()), FileChooser::Mode::save, {".json"}, start,
                                     [this](const std::filesystem::path& file) {
                                       try {
                                         writeAnswer(file);
                                         state_.setStatus(text::fill(language(), "handed in: {1}", {file.string()}), false);
                                       } catch (const Error& e) {
                                         state_.setStatus(e.what(), true);
                                       }
                                     });
}

void Exercises::endFrame() {
  if (!state_.practice || state_.practice->edits == state_.keptEdits || !shelf_.store) return;
  state_.keptEdits = state_.practice->edits;
  if (shelf_.store(exerciseKey(state_.practice->ref), practiceAnswer(*state_.practice).dump())) {
    keepError_.clear();
  } else if (keepError_.empty()) {
    keepError_ = text::Text("your answer could not be kept: the storage is full or not allowed").in(language());
    state_.setStatus(keepError_, true);
  }
}

Highlights::Student studentMarks(const PracticePart& p, const StepThrough& stepThrough) {
  if (!p.practice) return {};
  std::optional<int> pass;
  if (stepThrough.active && stepThrough.step >= 1) pass = stepThrough.step;
  const bool rowForm = p.check && p.check->grade.rowVectorForm;
  return practiceMarks(*p.practice, pass, rowForm);
}

}  // namespace vplab
