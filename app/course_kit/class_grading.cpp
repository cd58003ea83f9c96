#include "app/course_kit/class_grading.h"

#include "course/grade_report.h"
#include "course/assignment.h"
#include "course/grading.h"
#include "course/zip_archive.h"
#include "io/limits.h"
#include "io/read_file.h"
#include "io/scene_io.h"
#include "base/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

constexpr std::uintmax_t kMaxAnswerBytes = std::uintmax_t(64) << 20;  // as `vplab grade numbers`
constexpr size_t kMaxEntries = 20000;                                // entries of the answers folder
constexpr size_t kMaxVariantCheck = 2000;  // classes up to this size are checked for swapped variants

void writeFile(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw Error(file.string() + ": cannot write");
}

std::string pointsText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// A student's answer: a file of the answers folder, or an entry of the submissions zip (its text).
struct Submission {
  std::string name;  // relative to the answers folder or zip
  std::filesystem::path file;
  std::optional<std::string> text;
};

/// What one student's variant is graded against.
struct Variant {
  Assignment assignment;
  GradingReference reference;
  double maxPoints = 0;
};

Variant loadVariant(const std::filesystem::path& staff) {
  const std::filesystem::path file = staff / "assignment.json";
  Variant v{parseAssignment(readRegularFile(file, kDefaultLimits.sceneFileBytes, "assignment"), file.string()), {}, 0};
  if (v.assignment.scene.empty()) throw Error(file.string() + ": /scene: the assignment names no scene to grade against");
  v.reference = gradingReference(loadScene(staff / v.assignment.scene));
  for (const AssignmentItem& item : v.assignment.items) v.maxPoints += item.points;
  return v;
}

// An answer graded without follow-through: each item earns its points only when right.
void gradeWithoutFollowThrough(NumbersGrade& g) {
  g.points = 0;
  for (ItemGrade& item : g.items) {
    if (item.followsThrough) item.followsThrough = false, item.earned = 0;
    g.points += item.earned;
  }
}

/// How many of the answer's numbers under the assignment's items equal `reference`'s within the
/// tolerance (grading.h's rule).
size_t matchingValues(const Json& answer, const Variant& v) {
  size_t n = 0;
  for (const AssignmentItem& item : v.assignment.items) {
    const Json::json_pointer at(item.path);
    if (!answer.contains(at) || !v.reference.reference.contains(at)) continue;
    const Json flat = Json(answer.at(at)).flatten(), ref = Json(v.reference.reference.at(at)).flatten();
    for (const auto& [path, value] : flat.items()) {
      const auto a = answerNumber(value);
      if (!a || !ref.contains(path) || !ref[path].is_number()) continue;
      const double r = ref[path].get<double>();
      n += std::abs(*a - r) <= v.assignment.tolerance * std::max(1.0, std::abs(r));
    }
  }
  return n;
}

/// The submissions of the answers folder by student id; what matches no student goes to `unmatched`.
using Submissions = std::map<std::string, Submission>;

/// Records `sub` for student `id`, or why it is not matched.
void take(Submissions& found, const Roster& roster, std::vector<std::string>& unmatched, const std::string& id, Submission sub) {
  bool known = false;
  for (const RosterStudent& s : roster.students) known |= s.id == id;
  if (!known) return unmatched.push_back(sub.name + ": no student \"" + id + "\" in the roster");
  if (found.count(id)) return unmatched.push_back(sub.name + ": a second submission of \"" + id + "\" (the first is graded)");
  found[id] = std::move(sub);
}

/// Moodle's "Download all submissions" zip as it comes: entries "Name_N_assignsubmission_file_/X.json"
/// (answer.json, or the folder's only .json) and "ID.json"; the rest listed as not matched.
Submissions zipSubmissions(const std::filesystem::path& file, const Roster& roster, std::vector<std::string>& unmatched) {
  constexpr std::uintmax_t kMaxZipBytes = std::uintmax_t(1) << 30;
  const std::string zip = readRegularFile(file, kMaxZipBytes, "submissions zip");
  auto wanted = [](const std::string& name) {
    return name.size() > 5 && name.substr(name.size() - 5) == ".json" && std::count(name.begin(), name.end(), '/') <= 1;
  };
  std::map<std::string, std::vector<ZipEntry>> folders;  // folder → its .json entries
  Submissions found;
  for (ZipEntry& e : readZip(zip, file.string(), kMaxAnswerBytes, wanted)) {
    if (e.name.back() == '/') continue;
    const size_t slash = e.name.find('/');
    if (!wanted(e.name)) {
      if (slash == std::string::npos || e.name.find('/', slash + 1) != std::string::npos || !participantOfFolder(e.name.substr(0, slash)))
        unmatched.push_back(e.name + ": not an answer (.json) or in a submission folder");
      else
        folders[e.name.substr(0, slash)];  // a submission folder, perhaps without an answer
    } else if (slash == std::string::npos) {
      const std::string id = e.name.substr(0, e.name.size() - 5);
      take(found, roster, unmatched, id, {e.name, {}, std::move(e.data)});
    } else {
      folders[e.name.substr(0, slash)].push_back(std::move(e));
    }
  }
  for (auto& [folder, jsons] : folders) {
    const auto participant = participantOfFolder(folder);
    if (!participant) {
      unmatched.push_back(folder + "/: not a folder of Moodle's \"Download all submissions\" (Name_N_assignsubmission_file_)");
      continue;
    }
    ZipEntry* chosen = jsons.size() == 1 ? &jsons[0] : nullptr;
    for (ZipEntry& j : jsons)
      if (j.name == folder + "/answer.json") chosen = &j;
    if (!chosen)
      unmatched.push_back(folder + "/: " + (jsons.empty() ? std::string("no .json file")
                                                          : std::to_string(jsons.size()) + " .json files and none named answer.json"));
    else take(found, roster, unmatched, *participant, {chosen->name, {}, std::move(chosen->data)});
  }
  return found;
}

Submissions findSubmissions(const std::filesystem::path& dir, const Roster& roster, std::vector<std::string>& unmatched) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(dir, ec) && dir.extension() == ".zip") return zipSubmissions(dir, roster, unmatched);
  if (!std::filesystem::is_directory(dir, ec)) throw Error(dir.string() + ": not a folder of answers (nor a .zip of submissions)");
  Submissions found;
  size_t entries = 0;
  std::vector<std::filesystem::directory_entry> list;
  for (auto it = std::filesystem::directory_iterator(dir, ec); !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    if (++entries > kMaxEntries)
      throw Error(dir.string() + ": more than " + std::to_string(kMaxEntries) + " entries (the limit of one batch)");
    list.push_back(*it);
  }
  if (ec) throw Error(dir.string() + ": cannot list the folder: " + ec.message());
  std::sort(list.begin(), list.end());
  for (const auto& entry : list) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    const auto status = entry.symlink_status(ec);
    if (std::filesystem::is_symlink(status)) {
      unmatched.push_back(name + ": a link (not followed)");
    } else if (std::filesystem::is_regular_file(status) && entry.path().extension() == ".json") {
      take(found, roster, unmatched, entry.path().stem().string(), {name, entry.path(), {}});
    } else if (std::filesystem::is_directory(status)) {
      const auto participant = participantOfFolder(name);
      if (!participant) {
        unmatched.push_back(name + "/: not a folder of Moodle's \"Download all submissions\" (Name_N_assignsubmission_file_)");
        continue;
      }
      std::vector<std::filesystem::path> jsons;
      size_t inner = 0;
      for (auto it = std::filesystem::directory_iterator(entry.path(), ec); !ec && it != std::filesystem::directory_iterator();
           it.increment(ec)) {
        if (++inner > 100) break;
        if (it->path().extension() != ".json") continue;
        const auto st = it->symlink_status(ec);
        if (std::filesystem::is_symlink(st)) unmatched.push_back(name + "/" + it->path().filename().string() + ": a link (not followed)");
        else if (std::filesystem::is_regular_file(st)) jsons.push_back(it->path());
      }
      std::sort(jsons.begin(), jsons.end());
      std::filesystem::path chosen;
      for (const auto& j : jsons)
        if (j.filename() == "answer.json") chosen = j;
      if (chosen.empty() && jsons.size() == 1) chosen = jsons[0];
      if (chosen.empty())
        unmatched.push_back(name + "/: " + (jsons.empty() ? std::string("no .json file")
                                                           : std::to_string(jsons.size()) + " .json files and none named answer.json"));
      else
        take(found, roster, unmatched, *participant, {name + "/" + chosen.filename().string(), chosen, {}});
    } else {
      unmatched.push_back(name + ": not an answer (.json) or a submission folder");
    }
  }
  return found;
}

/// A name for a zip folder: the roster's full name without path separators or control characters.
std::string folderName(const std::string& name) {
  std::string out;
  for (unsigned char c : name) out += c < 0x20 || c == '/' || c == '\\' || c == 0x7F ? '_' : char(c);
  if (out.empty() || out == "." || out == "..") out = "student";
  return out.substr(0, 120);
}

std::string rowFeedback(const ClassRow& row, Language lang) {
  if (row.status == "no submission") return std::string(inLanguage(lang, "No submission.", "Keine Abgabe."));
  if (!row.error.empty()) return std::string(inLanguage(lang, "Could not be graded: ", "Nicht bewertbar: ")) + row.error;
  std::string f = pointsText(row.points) + std::string(inLanguage(lang, " of ", " von ")) + pointsText(row.maxPoints) +
                  std::string(inLanguage(lang, " points", " Punkten"));
  if (!row.otherVariant.empty())
    f += std::string(inLanguage(lang, "; the answer gives the values of another student's variant (",
                                "; die Antwort enthält die Werte der Variante eines anderen Studierenden (")) +
         row.otherVariant + std::string(inLanguage(lang, "), graded against your own", "), bewertet gegen Ihre eigene"));
  return f + std::string(inLanguage(lang, ". Details: report.md.", ". Einzelheiten: report.md."));
}

std::string gradesCsvOf(const ClassResult& r) {
  std::string out = csvRow({"student", "name", "file", "status", "points", "max_points", "passed", "other_variant", "error"});
  for (const ClassRow& row : r.rows)
    out += csvRow({row.student.id, row.student.fullName, row.file, row.status, pointsText(row.points),
                   pointsText(row.maxPoints), row.passed ? "yes" : "no", row.otherVariant, row.error});
  return out;
}

}  // namespace

ClassResult gradeClass(const ClassOptions& o) {
  ClassResult result;
  const std::filesystem::path rosterFile = o.exercises / "roster.csv";
  result.roster = parseRoster(readRegularFile(rosterFile, kMaxRosterBytes, "roster"), rosterFile.string());
  const Roster& roster = result.roster;
  std::vector<Variant> variants;
  for (const RosterStudent& s : roster.students) variants.push_back(loadVariant(o.exercises / "staff" / s.id));
  const auto submissions = findSubmissions(o.answers, roster, result.unmatched);
  std::error_code ec;
  std::filesystem::create_directories(o.out / "reports", ec);
  if (ec) throw Error((o.out / "reports").string() + ": cannot create the folder: " + ec.message());

  std::vector<std::pair<std::string, std::string>> feedbackFiles;
  for (size_t i = 0; i < roster.students.size(); ++i) {
    const RosterStudent& s = roster.students[i];
    const Variant& v = variants[i];
    ClassRow row;
    row.student = s;
    row.maxPoints = v.maxPoints;
    GradeReport report;
    const auto sub = submissions.find(s.id);
    if (sub == submissions.end()) {
      row.status = "no submission";
      report = errorReport("numbers", s.id, "scene.json", std::string(inLanguage(o.lang, "no submission", "keine Abgabe")), o.lang);
    } else {
      row.file = sub->second.name;
      try {
        const std::string text =
            sub->second.text ? *sub->second.text : readRegularFile(sub->second.file, kMaxAnswerBytes, "student's answer file");
        const Json answer = parseAnswer(text, row.file);
        NumbersGrade g = gradeNumbers(answer, row.file, v.reference, v.assignment.tolerance, &v.assignment);
        // Every answer short of full points (not only a failing one: follow-through can pass a copied
        // variant, e.g. 7 of 9 on the clipping sheet) is checked for another student's values.
        if (g.points < v.maxPoints && roster.students.size() <= kMaxVariantCheck) {
          size_t best = matchingValues(answer, v);
          for (size_t k = 0; k < variants.size(); ++k) {
            if (k == i) continue;
            const size_t m = matchingValues(answer, variants[k]);
            if (m > best) best = m, row.otherVariant = roster.students[k].id;
          }
        }
        // Follow-through credits work done right on one's own wrong values; another student's values
        // were not worked out from this student's data: only the items right for the own variant count.
        if (!row.otherVariant.empty()) gradeWithoutFollowThrough(g);
        report = numbersReport(g, row.file, "scene.json", o.lang, o.reveal);
        row.status = "graded";
        row.passed = g.passed();
        row.points = g.points;
        if (!row.otherVariant.empty()) {
          report.json["other_variant"] = row.otherVariant;
          report.diagnosis.insert(
              report.diagnosis.begin(),
              std::string(inLanguage(o.lang, "The answer's values are those of the variant of ",
                                     "Die Werte der Antwort sind die der Variante von ")) +
                  row.otherVariant +
                  std::string(inLanguage(o.lang,
                                         ", not of the student's own: graded against the own variant, without "
                                         "follow-through (the values were not worked out from the own data).",
                                         ", nicht der eigenen: bewertet gegen die eigene Variante, ohne Folgefehler "
                                         "(die Werte sind nicht aus den eigenen Angaben berechnet).")));
        }
      } catch (const std::exception& e) {  // Error, or bad_alloc on a hostile file: this student's row only
        row.status = "could not be graded";
        row.error = e.what();
        report = errorReport("numbers", row.file, "scene.json", e.what(), o.lang);
      }
    }
    report.id = s.id;
    row.feedback = rowFeedback(row, o.lang);
    const std::string text = reportText(report);
    const std::filesystem::path base = o.out / "reports" / s.id;
    writeFile(base.string() + ".txt", text);
    writeFile(base.string() + ".json", report.json.dump(2) + "\n");
    writeFile(base.string() + ".xml", reportJunit(report));
    feedbackFiles.emplace_back(folderName(s.fullName.empty() ? s.id : s.fullName) + "_" + s.id +
                                   "_assignsubmission_file_/report.md",
                               "# " + row.feedback + "\n\n```\n" + text + "```\n");
    result.rows.push_back(std::move(row));
  }

  std::vector<WorksheetGrade> grades;
  double maxPoints = 0;
  for (const ClassRow& row : result.rows) {
    grades.push_back({row.student.id, row.points, row.feedback});
    maxPoints = std::max(maxPoints, row.maxPoints);
  }
  writeFile(o.out / "grades.csv", gradesCsvOf(result));
  writeFile(o.out / "moodle-grading-worksheet.csv", moodleWorksheet(roster, grades, maxPoints));
  writeFile(o.out / "moodle-feedback-files.zip", storedZip(feedbackFiles));
  std::string unmatched;
  for (const std::string& u : result.unmatched) unmatched += u + "\n";
  writeFile(o.out / "unmatched.txt", unmatched);
  return result;
}

}  // namespace vplab
