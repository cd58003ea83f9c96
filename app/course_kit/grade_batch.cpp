#include "app/course_kit/grade_batch.h"

#include "course/grade_report.h"
#include "course/grading.h"
#include "io/limits.h"
#include "io/read_file.h"
#include "io/scene_io.h"
#include "base/error.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <thread>

namespace vplab {

using Json = nlohmann::ordered_json;

namespace {

constexpr std::uintmax_t kMaxAnswerBytes = std::uintmax_t(64) << 20;  // as `vplab grade numbers`

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void writeFile(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw Error(file.string() + ": cannot write");
}

// The answer files: the folder's regular files and links, not hidden ones, sorted by name; ids from
// the names without extension (the whole name where two share a stem).
std::vector<std::filesystem::path> answerFiles(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw Error(dir.string() + ": not a folder of answers");
  std::vector<std::filesystem::path> files;
  for (auto it = std::filesystem::directory_iterator(dir, ec); !ec && it != std::filesystem::directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.' || it->is_directory(ec)) continue;
    if (files.size() == kMaxBatchAnswers)
      throw Error(dir.string() + ": more than " + std::to_string(kMaxBatchAnswers) + " answer files (the limit of one batch)");
    files.push_back(it->path());
  }
  if (ec) throw Error(dir.string() + ": cannot list the folder: " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> idsOf(const std::vector<std::filesystem::path>& files) {
  std::map<std::string, int> stems;
  for (const auto& f : files) ++stems[f.stem().string()];
  std::vector<std::string> ids;
  for (const auto& f : files) ids.push_back(stems[f.stem().string()] > 1 ? f.filename().string() : f.stem().string());
  return ids;
}

// Autograder platforms' results format (Gradescope's results.json): the score, each test's.
Json platformResult(const GradeReport& r, const BatchRow& row) {
  std::string output;
  for (const std::string& d : r.diagnosis) output += d + "\n";
  Json tests = Json::array();
  for (const GradeCase& c : r.cases) {
    std::string text = c.message;
    for (const std::string& d : c.details) text += "\n" + d;
    tests.push_back({{"name", c.name},
                     {"score", c.points},
                     {"max_score", c.maxPoints},
                     {"status", c.passed ? "passed" : "failed"},
                     {"output", text}});
  }
  return {{"id", row.id},
          {"score", row.points},
          {"max_score", r.maxPoints},
          {"execution_time", row.seconds},
          {"output", output},
          {"tests", tests}};
}

}  // namespace

BatchResult gradeBatch(const BatchOptions& o, const std::function<void(size_t, size_t)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  BatchResult result;
  result.assignment = parseAssignment(readRegularFile(o.assignment, kDefaultLimits.sceneFileBytes, "assignment"),
                                      o.assignment.string());
  const Assignment& assignment = result.assignment;
  if (assignment.scene.empty()) throw Error(o.assignment.string() + ": /scene: the assignment names no scene to grade against");
  const std::filesystem::path sceneFile = o.assignment.parent_path() / assignment.scene;
  const GradingReference reference = gradingReference(loadScene(sceneFile));
  const std::vector<std::filesystem::path> files = answerFiles(o.answers);
  const std::vector<std::string> ids = idsOf(files);
  std::error_code ec;
  std::filesystem::create_directories(o.out / "reports", ec);
  if (ec) throw Error((o.out / "reports").string() + ": cannot create the folder: " + ec.message());

  result.rows.resize(files.size());
  std::vector<Json> platform(files.size());
  std::atomic<size_t> next{0};
  std::mutex mutex;
  size_t done = 0;
  std::string firstWriteError;
  auto work = [&] {
    for (size_t i; (i = next.fetch_add(1)) < files.size();) {
      const auto t0 = std::chrono::steady_clock::now();
      BatchRow& row = result.rows[i];
      row.id = ids[i];
      row.file = files[i].filename().string();
      row.itemPoints.assign(assignment.items.size(), 0);
      GradeReport report;
      try {
        const std::string text = readRegularFile(files[i], kMaxAnswerBytes, "student's answer file");
        const NumbersGrade g = gradeNumbers(parseAnswer(text, row.file), row.file, reference, assignment.tolerance, &assignment);
        report = numbersReport(g, row.file, sceneFile.filename().string(), o.lang, o.reveal);
        row.passed = g.passed();
        row.points = g.points;
        for (size_t k = 0; k < g.items.size(); ++k) row.itemPoints[k] = g.items[k].earned;
      } catch (const std::exception& e) {  // Error, or bad_alloc on a hostile file: this student's row only
        report = errorReport("numbers", row.file, sceneFile.filename().string(), e.what(), o.lang);
        report.graded = true;
        report.maxPoints = 0;
        for (const AssignmentItem& item : assignment.items) report.maxPoints += item.points;
        row.error = e.what();
      }
      report.id = row.id;
      row.seconds = report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      platform[i] = platformResult(report, row);
      try {
        const std::filesystem::path base = o.out / "reports" / row.id;
        writeFile(base.string() + ".txt", reportText(report));
        writeFile(base.string() + ".json", report.json.dump(2) + "\n");
        writeFile(base.string() + ".xml", reportJunit(report));
      } catch (const Error& e) {
        std::lock_guard lock(mutex);
        if (firstWriteError.empty()) firstWriteError = e.what();
      }
      std::lock_guard lock(mutex);
      ++done;
      if (progress) progress(done, files.size());
    }
  };
  const int jobs = std::clamp(o.jobs, 1, 256);
  std::vector<std::thread> workers;
  for (int j = 1; j < jobs && size_t(j) < files.size(); ++j) workers.emplace_back(work);
  work();
  for (std::thread& t : workers) t.join();
  if (!firstWriteError.empty()) throw Error(firstWriteError);

  double maxPoints = 0;
  for (const AssignmentItem& item : assignment.items) maxPoints += item.points;
  const Json results = {{"assignment", assignment.title}, {"max_score", maxPoints}, {"students", platform}};
  writeFile(o.out / "results.json", results.dump(2) + "\n");
  writeFile(o.out / "grades.csv", gradesCsv(result));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string gradesCsv(const BatchResult& r) {
  auto field = [](const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  double maxPoints = 0;
  for (const AssignmentItem& item : r.assignment.items) maxPoints += item.points;
  std::string out = "student,points,max_points,passed,error";
  for (const AssignmentItem& item : r.assignment.items) out += "," + field(item.title + " (" + number(item.points) + ")");
  out += "\n";
  for (const BatchRow& row : r.rows) {
    std::string error = row.error;
    std::replace(error.begin(), error.end(), '\n', ' ');
    out += field(row.id) + "," + number(row.points) + "," + number(maxPoints) + "," + (row.passed ? "yes" : "no") + "," +
           field(error);
    for (double p : row.itemPoints) out += "," + (row.error.empty() ? number(p) : std::string());
    out += "\n";
  }
  return out;
}

}  // namespace vplab
