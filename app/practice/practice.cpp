// Index: 1 opening  2 the sheet's texts  3 the answer  4 Check
#include "app/practice/practice.h"

#include "base/error.h"
#include "course/rational.h"
#include "course/sheet_values.h"
#include "io/json_read.h"
#include "io/limits.h"
#include "io/read_file.h"

#include <chrono>

namespace vplab {

using Json = nlohmann::ordered_json;

size_t Practice::firstField(size_t task) const {
  size_t first = 0;
  for (size_t t = 0; t < task && t < tasks.size(); ++t) first += tasks[t].items.size();
  return first;
}

// ---------------------------------------------------------------- 1 opening

Practice openPractice(const ExerciseRef& ref, Reveal reveal, Language lang) {
  Practice p;
  p.ref = ref;
  p.reveal = reveal;
  p.language = lang;
  p.exercise = generateExercise(ref.spec, ref.studentId);
  p.solution = solveExercise(p.exercise);
  // The assignment in the sheet's language is the one `vplab exercise` wrote: its item titles are what
  // the reports name; the panel's texts follow the UI's language (setPracticeLanguage).
  p.assignment = exerciseAssignment(p.exercise, p.solution, lang);
  p.tasks = exerciseTasks(p.exercise, p.solution, lang);
  p.grading = gradingReference(p.exercise.scene);
  // Hand in's answer.json names its exercise, so that it opens again on its own.
  p.answerTemplate = answerNamingExercise(answerTemplate(p.assignment, p.grading.reference), ref);
  p.fields = answerFields(p.assignment, answerKey(p.assignment, p.grading.reference));
  return p;
}

Practice openPracticeFolder(const std::filesystem::path& dir, Reveal reveal, Language lang) {
  const std::filesystem::path exerciseFile = dir / "exercise.json";
  std::error_code ec;
  if (!std::filesystem::exists(exerciseFile, ec))
    throw Error(exerciseFile.string() + ": no such file: the folder is not an exercise written by `vplab exercise`");
  const ExerciseRef ref =
      parseExerciseFile(readRegularFile(exerciseFile, kDefaultLimits.sceneFileBytes, "exercise"), exerciseFile.string());
  Practice p = openPractice(ref, reveal, lang);
  p.folder = dir;
  const std::filesystem::path answerFile = dir / "answer.json";
  if (std::filesystem::exists(answerFile, ec)) {
    const std::string text = readRegularFile(answerFile, kDefaultLimits.sceneFileBytes, "answer");
    fillFields(p.fields, parseAnswer(text, answerFile.string()));
  }
  return p;
}

Practice openPracticeFile(const std::filesystem::path& file, Reveal reveal, Language lang) {
  const std::string text = readRegularFile(file, kDefaultLimits.sceneFileBytes, "exercise");
  const Json j = parseAnswer(text, file.string());
  if (j.contains("vplab_exercise")) return openPracticeFolder(file.parent_path(), reveal, lang);
  const std::optional<ExerciseRef> ref = exerciseOfAnswer(j, file.string());
  if (!ref)
    throw Error(file.string() + ": neither an exercise.json nor an answer.json that names its exercise (/exercise): "
                "open the exercise.json of the folder your course gave you, or an answer handed in from vplab");
  Practice p = openPractice(*ref, reveal, lang);
  p.folder = file.parent_path();
  fillFields(p.fields, j);
  p.answerOpened = true;
  return p;
}

void setPracticeLanguage(Practice& p, Language lang) {
  if (p.language == lang) return;
  p.language = lang;
  p.tasks = exerciseTasks(p.exercise, p.solution, lang);
  const Assignment titled = exerciseAssignment(p.exercise, p.solution, lang);
  for (size_t i = 0; i < p.fields.size() && i < titled.items.size(); ++i) p.fields[i].item.title = titled.items[i].title;
  p.assignment = titled;
}

// ---------------------------------------------------------------- 2 the sheet's texts

namespace {

/// The projection as the sheet names it (the camera panel's words: app/text/ui_panels_camera_scene.inc).
std::string projectionName(Projection p, Language lang) {
  if (lang == Language::en) return std::string(toString(p));
  return p == Projection::perspective ? "perspektivisch" : p == Projection::parallel ? "parallel" : "schief";
}

std::string vec(const Vec3& v) { return "(" + plainNumber(v.x) + ", " + plainNumber(v.y) + ", " + plainNumber(v.z) + ")"; }

}  // namespace

std::vector<std::string> givenLines(const Practice& p, Language lang) {
  auto L = [&](const char* en, const char* de) { return std::string(lang == Language::de ? de : en); };
  const Camera& c = p.exercise.scene.camera;
  std::vector<std::string> lines = {
      "VRP = " + vec(c.vrp) + ", PRP = " + vec(c.prp) + ", VUP = " + vec(c.vup) + " (WC)",
      L("window ", "Fenster ") + "xmin = " + plainNumber(c.window.xmin) + ", xmax = " + plainNumber(c.window.xmax) +
          ", ymin = " + plainNumber(c.window.ymin) + ", ymax = " + plainNumber(c.window.ymax) + L(" (VRC)", " (VRC)"),
      "F = " + plainNumber(c.front) + ", B = " + plainNumber(c.back) + L(" (VRC z)", " (VRC z)"),
      L("projection: ", "Projektion: ") + projectionName(c.projection, lang) +
          (c.projection == Projection::oblique ? ", d = " + plainNumber(c.oblique.d) + ", φ = " + plainNumber(c.oblique.phiDeg) + "°" : ""),
      L("device ", "Ausgabegerät ") + std::to_string(p.exercise.scene.device.width) + " × " +
          std::to_string(p.exercise.scene.device.height) + L(" pixels, origin top left, y down", " Pixel, Ursprung oben links, y nach unten"),
  };
  const SceneObject& o = p.exercise.scene.objects[0];
  std::string polygon = L("the polygon in MC: ", "das Polygon in MC: ");
  for (size_t i = 0; i < o.vertices.size(); ++i) polygon += (i ? ", P" : "P") + std::to_string(i + 1) + " = " + vec(o.vertices[i]);
  lines.push_back(polygon);
  std::string model = "wcFromMc = T" + vec(o.transform.translate);
  for (auto it = o.transform.rotations.rbegin(); it != o.transform.rotations.rend(); ++it)
    model += " · R" + vec(it->axis) + "(" + plainNumber(it->deg) + "°)";
  model += " · S(" + plainNumber(o.transform.scale.x) + ")";
  lines.push_back(model);
  // What the sheet gives for a stage of its own (course/exercise.h): P1 in VRC for the mapping, the
  // polygon in homogeneous NPC for clipping.
  if (p.exercise.spec.topic == ExerciseTopic::mapping) lines.push_back(L("P1 in VRC = ", "P1 in VRC = ") + vec(p.solution.point.vrc));
  if (p.exercise.spec.topic == ExerciseTopic::clipping) {
    std::string npc = L("the polygon in homogeneous NPC: ", "das Polygon in homogenen NPC: ");
    for (size_t i = 0; i < p.solution.vertices.size(); ++i) {
      const Vec4& h = p.solution.vertices[i].npcH;
      npc += (i ? ", P" : "P") + std::to_string(i + 1) + " = (" + plainNumber(h.x) + ", " + plainNumber(h.y) + ", " +
             plainNumber(h.z) + ", " + plainNumber(h.w) + ")";
    }
    lines.push_back(npc);
  }
  return lines;
}

std::string plainMath(std::string_view latex) {
  std::string out;
  for (size_t i = 0; i < latex.size();) {
    const std::string_view rest = latex.substr(i);
    auto take = [&](std::string_view command, std::string_view text) {
      if (!rest.starts_with(command)) return false;
      out += text;
      i += command.size();
      return true;
    };
    // Subscripts read inline, as the panels name P1 and xmin.
    if (rest[0] == '$' || rest[0] == '{' || rest[0] == '}' || rest[0] == '_') {
      ++i;
      continue;
    }
    if (take("\\mathit", "") || take("\\cdot", "·") || take("\\times", "×") || take("\\le", "≤") ||
        take("\\to", "→") || take("\\varphi", "φ") || take("^\\circ", "°") || take("\\ ", " ") || take("\\,", " "))
      continue;
    out += rest[0];
    ++i;
  }
  return out;
}

// ---------------------------------------------------------------- 3 the answer

Json practiceAnswer(const Practice& p) { return answerOfFields(p.fields, p.answerTemplate); }

// ---------------------------------------------------------------- 4 Check

PracticeCheck checkPractice(const Practice& p, Language lang) {
  const auto start = std::chrono::steady_clock::now();
  PracticeCheck c;
  c.edits = p.edits;
  // The assignment as the sheet's file has it (its titles in the check's language): the same items,
  // points and rules as assignment.json.
  const Assignment assignment = exerciseAssignment(p.exercise, p.solution, lang);
  c.grade = gradeNumbers(practiceAnswer(p), "answer.json", p.grading, assignment.tolerance, &assignment);
  c.report = numbersReport(c.grade, "answer.json", "scene.json", lang, p.reveal);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  c.report.seconds = c.seconds;
  return c;
}

FieldVerdict fieldVerdict(const PracticeCheck& check, const ItemFields& f, int row, int column) {
  const std::string path = f.path(row, column);
  FieldVerdict worst = FieldVerdict::unchecked;
  auto rank = [](FieldVerdict v) {
    switch (v) {
      case FieldVerdict::unchecked: return 0;
      case FieldVerdict::right: return 1;
      case FieldVerdict::follows: return 2;
      case FieldVerdict::rounded: return 3;
      case FieldVerdict::wrong: return 4;
      case FieldVerdict::unreadable: return 5;
    }
    return 0;
  };
  for (const GradedValue& v : check.grade.values) {
    if (!(v.path == path || isWithin(path, v.path))) continue;
    const FieldVerdict verdict = v.malformed()   ? FieldVerdict::unreadable
                                 : v.right       ? FieldVerdict::right
                                 : v.consequent  ? FieldVerdict::follows
                                 : v.rounded     ? FieldVerdict::rounded
                                                 : FieldVerdict::wrong;
    if (rank(verdict) > rank(worst)) worst = verdict;
  }
  return worst;
}

}  // namespace vplab
