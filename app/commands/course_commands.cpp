#include "app/commands/course_commands.h"
#include "app/commands/number_argument.h"
#include "app/export/progress_bar.h"

#include "app/course_kit/class_exercise.h"
#include "app/course_kit/class_grading.h"
#include "app/course_kit/exercise_writer.h"
#include "app/course_kit/grade_batch.h"
#include "app/course_kit/grade_image.h"
#include "app/course_kit/image_report.h"
#include "course/exercise_file.h"
#include "app/render/headless.h"
#include "course/assignment.h"
#include "course/moodle_bank.h"
#include "course/roster.h"
#include "base/error.h"
#include "io/read_file.h"
#include "io/limits.h"
#include "io/scene_io.h"

#include <CLI/CLI.hpp>
#include <stb_image.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

namespace vplab {

namespace {

constexpr int kMaxGradeSide = 8192;

/// A usage or input error: exit status 2.
struct UsageError : Error {
  using Error::Error;
};

struct ExerciseArgs {
  std::string seed = "1";
  std::string topic = "pipeline", projection = "perspective", lang = "en", out, studentId, roster, moodle;
};

struct GradeArgs {
  std::string scene, student, junit, view = "camera", style = "flat", diff, backend = "auto", assignment, lang = "en";
  std::string reveal = "values";
  // Numbers as text, converted here, so that a bad value is a usage error (exit 2) like the others;
  // empty: the default (or the assignment's).
  std::string tolerance, maxDiff = "48", meanDiff = "2", maxShare = "0.005", maxShift = "1";
  bool json = false;
};

Reveal revealOf(const std::string& reveal) {
  const std::optional<Reveal> r = fromString<Reveal>(reveal);
  if (!r) throw UsageError("--reveal \"" + reveal + "\": values, stages or none expected");
  return *r;
}

Language languageOf(const std::string& lang) {
  if (lang != "en" && lang != "de") throw UsageError("--lang \"" + lang + "\": en or de expected");
  return lang == "de" ? Language::de : Language::en;
}

double number(const std::string& option, const std::string& text, double lo, double hi) {
  if (const std::optional<double> v = numberArgument(text, lo, hi)) return *v;
  throw UsageError(option + " \"" + text + "\": a number from " + format(lo) + " to " + format(hi) + " expected");
}

/// Arguments CLI11 did not recognise (the subcommands allow extras so that they end here, with exit 2).
void noExtras(const CLI::App* cmd) {
  const std::vector<std::string> extra = cmd->remaining();
  if (extra.empty()) return;
  std::string list;
  for (const std::string& e : extra) list += (list.empty() ? "" : " ") + e;
  throw UsageError("unexpected argument(s): " + list + " (see --help)");
}

Scene gradeScene(const std::string& path) {
  try {
    return path.empty() ? defaultScene() : loadScene(path);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

/// A student's answer: a regular file of at most 64 MiB (a whole dump of the bundled scenes is far
/// smaller), checked before it is read, so /dev/zero or a FIFO is an input error and not a hang.
std::string readAnswer(const std::string& path) {
  constexpr std::uintmax_t kMaxAnswerBytes = std::uintmax_t(64) << 20;
  try {
    return readRegularFile(path, kMaxAnswerBytes, "student's answer file");
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

void writeJunit(const GradeReport& report, const std::string& file) {
  std::ofstream out(file, std::ios::binary);
  out << reportJunit(report);
  if (!out) throw Error(file + ": cannot write the JUnit report");
}

void emit(const GradeReport& report, const GradeArgs& a) {
  if (a.json)
    std::cout << report.json.dump(2) << "\n";
  else
    std::cout << reportText(report);
  if (!a.junit.empty()) writeJunit(report, a.junit);
}

/// Runs `grade`; an answer that cannot be graded (unreadable, malformed) still gets its report:
/// the JUnit file (and --json's report) names the problem, and the exit status is 2.
template <class F>
int gradeOrReport(const GradeArgs& a, const std::string& kind, const std::string& scene, F&& grade) {
  const auto start = std::chrono::steady_clock::now();
  try {
    GradeReport report = grade();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    emit(report, a);
    return report.passed ? 0 : 1;
  } catch (const UsageError& e) {
    if (!a.junit.empty() || a.json) {
      GradeReport report = errorReport(kind, a.student, scene, e.what(), languageOf(a.lang));
      report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (a.json) std::cout << report.json.dump(2) << "\n";
      if (!a.junit.empty()) writeJunit(report, a.junit);
    }
    throw;
  }
}

int gradeNumbersCommand(const GradeArgs& a) {
  if (a.student.empty()) throw UsageError("grade numbers: --student FILE is required");
  const Language lang = languageOf(a.lang);
  const Reveal reveal = revealOf(a.reveal);
  std::optional<Assignment> assignment;
  std::string sceneFile = a.scene;
  if (!a.assignment.empty()) {
    try {
      assignment = parseAssignment(readRegularFile(a.assignment, kDefaultLimits.sceneFileBytes, "assignment"), a.assignment);
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
    if (sceneFile.empty() && !assignment->scene.empty())
      sceneFile = (std::filesystem::path(a.assignment).parent_path() / assignment->scene).string();
  }
  const double tolerance = !a.tolerance.empty() ? number("--tolerance", a.tolerance, 0, 0.5)
                                                : assignment ? assignment->tolerance : 1e-3;
  const std::string sceneName = sceneFile.empty() ? "(built-in default scene)" : sceneFile;
  const Scene scene = gradeScene(sceneFile);
  return gradeOrReport(a, "numbers", sceneName, [&] {
    const std::string text = readAnswer(a.student);
    NumbersGrade grade;
    try {
      grade = gradeNumbers(parseAnswer(text, a.student), a.student, scene, tolerance, assignment ? &*assignment : nullptr);
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
    return numbersReport(grade, a.student, sceneName, lang, reveal);
  });
}

int gradeImageCommand(const GradeArgs& a) {
  if (a.student.empty()) throw UsageError("grade image: --student FILE.png is required");
  const auto view = fromString<ViewKind>(a.view);
  if (!view || *view == ViewKind::morph || *view == ViewKind::all)
    throw UsageError("--view \"" + a.view + "\": camera, world or npc expected");
  const auto style = fromString<Style>(a.style);
  if (!style) throw UsageError("--style \"" + a.style + "\": flat, shaded, wire, hidden-line or hidden-removed expected");
  const auto backend = fromString<Backend>(a.backend);
  if (!backend) throw UsageError("--backend \"" + a.backend + "\": auto, egl or osmesa expected");
  const Language lang = languageOf(a.lang);
  ImageThresholds t;
  const double maxDiff = number("--max-diff", a.maxDiff, 0, 255);
  if (maxDiff != std::floor(maxDiff)) throw UsageError("--max-diff \"" + a.maxDiff + "\": a whole number from 0 to 255 expected");
  t.maxDiff = int(maxDiff);
  t.meanDiff = number("--mean-diff", a.meanDiff, 0, 255);
  t.maxShare = number("--max-share", a.maxShare, 0, 1);
  const double maxShift = number("--max-shift", a.maxShift, 0, kShiftSearch);
  if (maxShift != std::floor(maxShift))
    throw UsageError("--max-shift \"" + a.maxShift + "\": a whole number from 0 to " + std::to_string(kShiftSearch) + " expected");
  t.maxShift = int(maxShift);
  const Scene scene = gradeScene(a.scene);
  const std::string sceneName = a.scene.empty() ? "(built-in default scene)" : a.scene;
  return gradeOrReport(a, "image", sceneName, [&] {
    // The size from the PNG header first: a hostile file must not make us allocate (or render) gigabytes.
    int width = 0, height = 0, channels = 0;
    // Within the render's pixel budget too (io/limits.h): the reference is rendered at the student's size.
    if (stbi_info(a.student.c_str(), &width, &height, &channels) &&
        (width > kMaxGradeSide || height > kMaxGradeSide || std::int64_t(width) * height > kMaxImagePixels))
      throw UsageError(a.student + ": " + std::to_string(width) + " × " + std::to_string(height) + " pixels; at most " +
                       std::to_string(kMaxGradeSide) + " on each side and " + std::to_string(kMaxImagePixels) +
                       " in all (8K UHD, the render's budget) are graded");
    Image student;
    try {
      student = readPng(a.student);
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
    auto context = createHeadlessContext(*backend, false);
    ViewRenderer renderer(*context);
    const ImageGrade grade = gradeImage(renderer, scene, student, *view, *style, t);
    const std::string diff = a.diff.empty() ? a.student + ".diff.png" : a.diff;
    if (!grade.comparison.sizeMismatch) writePng(grade.difference, diff);
    return imageReport(grade, a.student, sceneName, grade.comparison.sizeMismatch ? "" : diff, lang);
  });
}

struct BatchArgs {
  std::string assignment, exercises, answers, out = "grades", jobs, lang = "en", reveal = "values";
};

/// `grade batch --exercises DIR`: every roster student against their own variant (class_grading.h).
int gradeClassCommand(const BatchArgs& a) {
  if (!a.assignment.empty()) throw UsageError("grade batch: --assignment and --exercises exclude each other");
  ClassOptions o;
  o.exercises = a.exercises;
  o.answers = a.answers;
  o.out = a.out;
  o.lang = languageOf(a.lang);
  o.reveal = revealOf(a.reveal);
  ClassResult r;
  try {
    r = gradeClass(o);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  size_t passed = 0, missing = 0, errors = 0, swapped = 0;
  for (const ClassRow& row : r.rows)
    passed += row.passed, missing += row.status == "no submission", errors += !row.error.empty(),
        swapped += !row.otherVariant.empty();
  std::cout << "vplab grade batch: " << r.rows.size() << " students: " << passed << " passed, "
            << r.rows.size() - passed - missing - errors << " failed, " << missing << " no submission, " << errors
            << " could not be graded, " << swapped << " with another student's variant; " << r.unmatched.size()
            << " files not matched to the roster" << (r.unmatched.empty() ? "" : " (unmatched.txt)") << "\n";
  for (const std::string& u : r.unmatched) std::cout << "  not matched: " << u << "\n";
  std::cout << "wrote grades.csv, moodle-grading-worksheet.csv, moodle-feedback-files.zip and reports/ to " << a.out << "\n";
  return 0;
}

int gradeBatchCommand(const BatchArgs& a) {
  if (a.answers.empty()) throw UsageError("grade batch: --answers DIR is required");
  if (!a.exercises.empty()) return gradeClassCommand(a);
  if (a.assignment.empty()) throw UsageError("grade batch: --assignment FILE is required (or --exercises DIR for a class)");
  BatchOptions o;
  o.assignment = a.assignment;
  o.answers = a.answers;
  o.out = a.out;
  o.lang = languageOf(a.lang);
  o.reveal = revealOf(a.reveal);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  o.jobs = a.jobs.empty() ? int(cores) : int(number("--jobs", a.jobs, 1, 256));
  if (!a.jobs.empty() && std::to_string(o.jobs) != a.jobs) throw UsageError("--jobs \"" + a.jobs + "\": a whole number from 1 to 256 expected");
  ProgressBar progress("vplab grade batch", "graded");  // on stderr: a bar on a terminal, else a line every tenth
  BatchResult r;
  try {
    r = gradeBatch(o, std::ref(progress));
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  size_t passed = 0, errors = 0;
  for (const BatchRow& row : r.rows) passed += row.passed, errors += !row.error.empty();
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.2f", r.seconds);
  std::cout << "vplab grade batch: " << r.rows.size() << " answers in " << seconds << " s with " << o.jobs
            << (o.jobs == 1 ? " job" : " jobs") << ": " << passed << " passed, " << r.rows.size() - passed - errors
            << " failed, " << errors << " could not be graded; " << (std::filesystem::path(a.out) / "grades.csv").string()
            << ", results.json and reports/ written\n";
  return 0;
}

void writeBank(const std::string& file, const std::string& xml) {
  std::ofstream out(file, std::ios::binary);
  out << xml;
  if (!out) throw Error(file + ": cannot write the Moodle question bank");
}

/// `vplab exercise --roster`: one variant per student (app/course_kit/class_exercise.h), and their bank.
int classExerciseCommand(const ExerciseArgs& a, const ExerciseSpec& spec, Language lang) {
  if (!a.studentId.empty()) throw UsageError("--student-id and --roster exclude each other (the roster names the students)");
  std::string text;
  Roster roster;
  try {
    text = readRegularFile(a.roster, kMaxRosterBytes, "roster");
    roster = parseRoster(text, a.roster);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  const std::vector<MoodleQuestion> questions = writeClassExercises(spec, roster, text, lang, a.out, !a.moodle.empty());
  if (!a.moodle.empty()) writeBank(a.moodle, moodleBankXml(moodleCategory(spec), questions));
  std::cerr << "vplab exercise: wrote " << roster.students.size() << " variants to " << a.out
            << " (students/ID: the sheets and answer.json; staff/ID: solutions and assignment.json)"
            << (a.moodle.empty() ? "" : " and the Moodle question bank " + a.moodle) << "\n";
  return 0;
}

int exerciseCommand(const ExerciseArgs& a) {
  if (a.out.empty()) throw UsageError("exercise: --out DIR is required");
  const auto topic = fromString<ExerciseTopic>(a.topic);
  if (!topic) throw UsageError("--topic \"" + a.topic + "\": orientation, mapping, clipping or pipeline expected");
  const auto projection = fromString<Projection>(a.projection);
  if (!projection) throw UsageError("--projection \"" + a.projection + "\": perspective, parallel or oblique expected");
  if (a.lang != "en" && a.lang != "de") throw UsageError("--lang \"" + a.lang + "\": en or de expected");
  const std::optional<uint64_t> seed = exerciseSeedFrom(a.seed);
  if (!seed) throw UsageError("--seed \"" + a.seed + "\": a whole number from 0 to 999999999999999999 expected");
  // The id is printed on the sheet (Markdown and LaTeX): letters, digits, '.', '-' and '@' only.
  if (!a.studentId.empty() && !validStudentId(a.studentId))
    throw UsageError("--student-id \"" + a.studentId + "\": at most 64 letters, digits, '.', '-' or '@' expected");
  const ExerciseSpec spec{*seed, *topic, *projection};
  const Language lang = a.lang == "de" ? Language::de : Language::en;
  if (!a.roster.empty()) return classExerciseCommand(a, spec, lang);
  const Exercise exercise = generateExercise(spec, a.studentId);
  writeExercise(exercise, lang, a.out);
  if (!a.moodle.empty()) {
    writeBank(a.moodle, moodleBankXml(moodleCategory(spec), {moodleQuestion(exercise, lang, a.out)}));
    std::cerr << "vplab exercise: wrote the Moodle question bank " << a.moodle << "\n";
  }
  std::cerr << "vplab exercise: wrote sheet.md, solution.md, sheet.tex, solution.tex, scene.json, exercise.json, answer.json (the template to fill in), solution.json (its key), assignment.json (for vplab grade) and the figures to "
            << a.out << "\n";
  return 0;
}

/// Runs a command and ends the parse with its exit code (CLI::App::exit returns it).
/// `failure`: the exit code of an error that is not the user's (exercise: 1; grade: 2, "could not
/// grade", as 1 means "graded: wrong").
template <class F>
[[noreturn]] void finish(const CLI::App* cmd, int failure, F&& run) {
  int code = 0;
  try {
    noExtras(cmd);
    code = run();
  } catch (const UsageError& e) {
    std::cerr << "vplab: error: " << e.what() << "\n";
    code = 2;
  } catch (const Error& e) {
    std::cerr << "vplab: error: " << e.what() << "\n";
    code = failure;
  } catch (const std::exception& e) {
    std::cerr << "vplab: unexpected error: " << e.what() << "\n";
    code = 2;
  }
  throw CLI::RuntimeError(code);
}

void addGradeOptions(CLI::App* cmd, GradeArgs& a) {
  cmd->add_option("--scene", a.scene, "The assignment's scene file (JSON); default: the built-in lecture scene")
      ->type_name("FILE");
  cmd->add_option("--student", a.student, "The student's answer file (required)")
      ->type_name("FILE");
  cmd->add_flag("--json", a.json, "Print the report as JSON instead of text");
  cmd->add_option("--junit", a.junit,
                  "Also write the report as JUnit XML to FILE (for autograders; written for a malformed answer too)")
      ->type_name("FILE");
  cmd->add_option("--lang", a.lang, "The feedback's language: en (default) or de")
      ->type_name("LANG");
  cmd->add_option("--reveal", a.reveal,
                  "What the feedback shows of the reference: values (default), stages (the first departing stage and "
                  "the mistake, no reference value) or none (which values are wrong, and the points)")
      ->type_name("WHAT");
}

}  // namespace

void addCourseCommands(CLI::App& app) {
  auto ex = std::make_shared<ExerciseArgs>();
  CLI::App* exercise = app.add_subcommand(
      "exercise", "Write an exercise sheet and its worked solution (Markdown and LaTeX, with figures) into --out DIR");
  exercise->add_option("--seed", ex->seed, "The exercise's number: the same seed gives the same files")
      ->type_name("N");
  exercise->add_option("--topic", ex->topic, "orientation, mapping, clipping or pipeline (the default: all stages)")
      ->type_name("TOPIC");
  exercise->add_option("--projection", ex->projection, "perspective (default), parallel or oblique")
      ->type_name("PROJECTION");
  exercise->add_option("--lang", ex->lang, "en (default) or de")
      ->type_name("LANG");
  exercise->add_option("--student-id", ex->studentId,
                       "A student's own variant of the exercise: other numbers, the same tasks and difficulty "
                       "(the same id gives the same bytes)")
      ->type_name("ID");
  exercise->add_option("--roster", ex->roster,
                       "A class: one variant per student of ROSTER.csv (an `id` column, or Moodle's grading worksheet) "
                       "into --out DIR/students/ID and DIR/staff/ID")
      ->type_name("ROSTER.csv");
  exercise->add_option("--moodle", ex->moodle,
                       "Also write a Moodle XML question bank: one cloze question per variant, with the key's values, "
                       "their tolerance and the mistakes' values")
      ->type_name("BANK.xml");
  exercise->add_option("--out", ex->out, "The folder to write to (created; required)")
      ->type_name("DIR");
  exercise->allow_extras();
  exercise->callback([ex, exercise] { finish(exercise, 1, [&] { return exerciseCommand(*ex); }); });

  CLI::App* grade = app.add_subcommand(
      "grade", "Compare a student's numbers (grade numbers) or screenshot (grade image) with the reference and name "
               "the mistake. Exit status 0 passed, 1 wrong, 2 usage or input error");
  grade->callback([grade] {  // runs only when no subcommand ended the parse
    finish(grade, 2, []() -> int { throw UsageError("grade: a subcommand is required: numbers, image or batch"); });
  });
  auto num = std::make_shared<GradeArgs>();
  CLI::App* numbers = grade->add_subcommand(
      "numbers", "Grade a student's numbers in the `vplab dump` format (any subset of it) value by value");
  addGradeOptions(numbers, *num);
  numbers->add_option("--tolerance", num->tolerance,
                      "A number is right when |student − reference| ≤ T · max(1, |reference|); default: the "
                      "assignment's, else 0.001")
      ->type_name("T");
  numbers->add_option("--assignment", num->assignment,
                      "What the answer must give and what each item is worth (assignment.json of vplab exercise); "
                      "its scene is graded unless --scene says otherwise")
      ->type_name("FILE");
  numbers->allow_extras();
  numbers->callback([num, numbers] { finish(numbers, 2, [&] { return gradeNumbersCommand(*num); }); });

  auto bat = std::make_shared<BatchArgs>();
  CLI::App* batch = grade->add_subcommand(
      "batch", "Grade a class: every answer file in --answers DIR (one per student, named by the student's id) "
               "against --assignment, in parallel; writes grades.csv, results.json and reports/ into --out DIR");
  batch->add_option("--assignment", bat->assignment, "The assignment (assignment.json of vplab exercise; required without --exercises)")
      ->type_name("FILE");
  batch->add_option("--exercises", bat->exercises,
                    "A class's exercises (--out DIR of vplab exercise --roster): each student graded against their own "
                    "variant; also writes moodle-grading-worksheet.csv and moodle-feedback-files.zip")
      ->type_name("DIR");
  batch->add_option("--answers", bat->answers,
                    "The folder of answer files (required): ID.json, or Moodle's \"Download all submissions\" (its zip, "
                    "or unpacked)")
      ->type_name("DIR");
  batch->add_option("--out", bat->out, "Where to write the gradebook and the reports (default: grades)")
      ->type_name("DIR");
  batch->add_option("--jobs", bat->jobs, "Answers graded at once (default: the number of cores)")
      ->type_name("N");
  batch->add_option("--lang", bat->lang, "The feedback's language: en (default) or de")
      ->type_name("LANG");
  batch->add_option("--reveal", bat->reveal,
                    "What each report shows of the reference: values (default), stages or none (see grade numbers)")
      ->type_name("WHAT");
  batch->allow_extras();
  batch->callback([bat, batch] { finish(batch, 2, [&] { return gradeBatchCommand(*bat); }); });

  auto img = std::make_shared<GradeArgs>();
  CLI::App* image = grade->add_subcommand(
      "image", "Grade a student's screenshot (PNG) against the reference rendered headless at its size");
  addGradeOptions(image, *img);
  image->add_option("--view", img->view, "camera (default), world or npc")
      ->type_name("VIEW");
  image->add_option("--style", img->style, "flat (default), shaded, wire, hidden-line or hidden-removed")
      ->type_name("STYLE");
  image->add_option("--max-diff", img->maxDiff,
                    "A pixel is wrong when a channel differs by more than N (0..255, default 48)")
      ->type_name("N");
  image->add_option("--mean-diff", img->meanDiff,
                    "The mean channel difference may be at most M (default 2.0)")
      ->type_name("M");
  image->add_option("--max-share", img->maxShare, "At most this share of pixels may be wrong (default 0.005)")
      ->type_name("P");
  image->add_option("--max-shift", img->maxShift,
                    "A picture shifted by at most N px on each axis is compared at its shift; a larger shift fails, "
                    "named (0..16, default 1)")
      ->type_name("N");
  image->add_option("--diff", img->diff, "Where to write the difference image (default: STUDENT.diff.png)")
      ->type_name("FILE");
  image->add_option("--backend", img->backend, "Headless OpenGL: auto (EGL, then OSMesa), egl or osmesa")
      ->type_name("BACKEND");
  image->allow_extras();
  image->callback([img, image] { finish(image, 2, [&] { return gradeImageCommand(*img); }); });
}

}  // namespace vplab
