#include "app/course_kit/class_exercise.h"

#include "app/course_kit/exercise_writer.h"
#include "course/exercise_answer.h"
#include "course/grading.h"
#include "course/sheet_values.h"
#include "io/read_file.h"
#include "base/error.h"

#include <cstdlib>
#include <fstream>

namespace vplab {

namespace {

constexpr std::uintmax_t kMaxFigureBytes = std::uintmax_t(16) << 20;

void writeText(const std::string& text, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw Error(file.string() + ": cannot write");
}

bool pdflatexInstalled() { return std::system("command -v pdflatex >/dev/null 2>&1") == 0; }

/// sheet.pdf from sheet.tex in `dir` (twice is not needed: the sheet has no references). `dir` is
/// made of the output folder and a checked id (roster.h validStudentId), quoted for the shell.
void compileSheet(const std::filesystem::path& dir) {
  std::string quoted = "'";
  for (char c : dir.string()) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  const std::string command = "cd " + quoted +
                              " && pdflatex -interaction=nonstopmode -halt-on-error sheet.tex >/dev/null 2>&1"
                              " && rm -f sheet.aux sheet.log";
  if (std::system(command.c_str()) != 0) throw Error((dir / "sheet.tex").string() + ": pdflatex failed (see sheet.log there)");
}

}  // namespace

const std::vector<std::string>& studentFiles() {
  // exercise.json: the folder opens in the viewer (`vplab --exercise DIR`, issue 40).
  static const std::vector<std::string> files = {"sheet.md", "sheet.tex", "answer.json", "scene.json", "exercise.json",
                                                 "world.svg", "world.png"};
  return files;
}

std::string moodleCategory(const ExerciseSpec& spec) {
  return "vplab/Exercise " + std::to_string(spec.seed) + " (" + std::string(toString(spec.topic)) + ", " +
         std::string(toString(spec.projection)) + ")";
}

MoodleQuestion moodleQuestion(const Exercise& exercise, Language lang, const std::filesystem::path& dir) {
  const ExerciseSolution solution = solveExercise(exercise);
  const Assignment assignment = exerciseAssignment(exercise, solution, lang);
  const GradingReference reference = gradingReference(exercise.scene);
  MoodleQuestion q;
  q.lang = lang;
  q.name = std::string(inLanguage(lang, "Exercise ", "Übung ")) + std::to_string(exercise.spec.seed) + " (" +
           std::string(toString(exercise.spec.topic)) + ", " + std::string(toString(exercise.spec.projection)) + ")" +
           (exercise.studentId.empty() ? "" : std::string(inLanguage(lang, " for ", " für ")) + exercise.studentId);
  q.sheetMarkdown = exerciseDocuments(exercise, solution, lang).sheetMd;
  q.figures.push_back({"world.png", readRegularFile(dir / "world.png", kMaxFigureBytes, "figure")});
  q.values = clozeValues(assignment, answerKey(assignment, reference.reference), reference.models, lang);
  return q;
}

std::vector<MoodleQuestion> writeClassExercises(const ExerciseSpec& spec, const Roster& roster, std::string_view rosterText,
                                                Language lang, const std::filesystem::path& out, bool withQuestions) {
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) throw Error(out.string() + ": cannot create the folder: " + ec.message());
  writeText(std::string(rosterText), out / "roster.csv");
  const bool pdf = pdflatexInstalled();
  std::vector<MoodleQuestion> questions;
  for (const RosterStudent& s : roster.students) {
    if (!validStudentId(s.id)) throw Error("roster: id \"" + s.id + "\" cannot name a folder");
    const Exercise exercise = generateExercise(spec, s.id);
    const std::filesystem::path staff = out / "staff" / s.id, student = out / "students" / s.id;
    writeExercise(exercise, lang, staff);
    std::filesystem::create_directories(student, ec);
    if (ec) throw Error(student.string() + ": cannot create the folder: " + ec.message());
    for (const std::string& f : studentFiles()) {
      std::filesystem::copy_file(staff / f, student / f, std::filesystem::copy_options::overwrite_existing, ec);
      if (ec) throw Error((student / f).string() + ": cannot write: " + ec.message());
    }
    if (pdf) compileSheet(student);
    if (withQuestions) questions.push_back(moodleQuestion(exercise, lang, staff));
  }
  return questions;
}

}  // namespace vplab
