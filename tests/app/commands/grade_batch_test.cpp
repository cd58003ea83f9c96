// `vplab grade batch` (issue 21): a generated class of 300 answers (right ones, each mistake model,
// unknown mistakes, rounding, empty answers, the untouched template and hostile files) gives the
// expected gradebook, every student gets reports, and no file ends the batch.
#include "course/assignment.h"
#include "course/mistake_models.h"
#include "course/sheet_values.h"
#include "io/scene_io.h"
#include "tests/support/files.h"
#include "tests/support/process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using ::testing::HasSubstr;
using test::readFile;
using test::shellQuoted;

class GradeBatch : public test::ProcessTest {
 protected:
  test::ProcessResult vplab(const std::string& args) { return sh(shellQuoted(VPLAB_EXE) + " " + args); }
};

Json rounded(const Json& j, int decimals) {
  if (j.is_number_float()) return std::round(j.get<double>() * std::pow(10.0, decimals)) / std::pow(10.0, decimals);
  Json out = j;
  if (j.is_structured())
    for (auto it = out.begin(); it != out.end(); ++it) *it = rounded(*it, decimals);
  return out;
}

// The answer an assignment asks for, its values taken from `source` (a reference or a model's answer).
Json filled(const Assignment& a, const Json& blank, const Json& source) {
  Json answer = blank;
  for (const AssignmentItem& item : a.items) answer[Json::json_pointer(item.path)] = source[Json::json_pointer(item.path)];
  return answer;
}

std::map<std::string, std::vector<std::string>> csvRows(const std::string& csv) {
  std::map<std::string, std::vector<std::string>> rows;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) cells.push_back(cell), cell.clear();
      else cell += c;
    }
    cells.push_back(cell);
    rows[cells[0]] = cells;
  }
  return rows;
}

TEST_F(GradeBatch, AGeneratedClassGivesTheExpectedGradebook) {
  ASSERT_EQ(vplab("exercise --seed 5 --topic pipeline --out sheet").exitCode, 0);
  // Without the sheet's pass mark (half the points), passed means every value right: what the
  // expectations below count.
  Json assignmentJson = Json::parse(readFile(dir_ / "sheet" / "assignment.json"));
  assignmentJson.erase("pass_mark");
  std::ofstream(dir_ / "sheet" / "assignment.json") << assignmentJson.dump(2);
  const Assignment a = parseAssignment(readFile(dir_ / "sheet" / "assignment.json"), "assignment.json");
  const Json blank = Json::parse(readFile(dir_ / "sheet" / "answer.json"));
  const Scene scene = loadScene(dir_ / "sheet" / "scene.json");
  const Json reference = referenceAnswer(scene);
  double maxPoints = 0;
  for (const AssignmentItem& i : a.items) maxPoints += i.points;
  fs::create_directories(dir_ / "class");
  auto write = [&](const std::string& name, const std::string& text) { std::ofstream(dir_ / "class" / name) << text; };
  std::map<std::string, std::string> expected;  // id → "pass", "fail", "error"
  for (int i = 0; i < 70; ++i) write("right" + std::to_string(i) + ".json", filled(a, blank, reference).dump()), expected["right" + std::to_string(i)] = "pass";
  for (const MistakeModel& m : mistakeModels()) {
    Json model = mistakeDump(scene, m.id);
    addSheetValues(model, m.id == Mistake::transposed, m.id == Mistake::divideFirst);
    const Json answer = filled(a, blank, model);
    for (int i = 0; i < 15; ++i) {
      const std::string id = std::string(m.key) + std::to_string(i);
      write(id + ".json", answer.dump());
      // A model may not show on this sheet; every matrix transposed is the row-vector notation (issue 38).
      expected[id] = answer == filled(a, blank, reference) || m.id == Mistake::transposed ? "pass" : "fail";
    }
  }
  for (int i = 0; i < 30; ++i) write("rounded" + std::to_string(i) + ".json", rounded(filled(a, blank, reference), 1).dump()), expected["rounded" + std::to_string(i)] = "fail";
  for (int i = 0; i < 20; ++i) {
    Json answer = filled(a, blank, reference);
    answer["camera"]["vpd"] = answer["camera"]["vpd"].get<double>() + 1 + i;  // an unknown mistake
    write("unknown" + std::to_string(i) + ".json", answer.dump());
    expected["unknown" + std::to_string(i)] = "fail";
  }
  for (int i = 0; i < 24; ++i) write("empty" + std::to_string(i) + ".json", "{}"), expected["empty" + std::to_string(i)] = "fail";
  for (int i = 0; i < 10; ++i) write("template" + std::to_string(i) + ".json", blank.dump()), expected["template" + std::to_string(i)] = "fail";
  // Hostile and broken files: each is its student's error row.
  const std::map<std::string, std::string> hostile = {
      {"deep", std::string(100000, '[')},
      {"garbage", std::string("\x00\xff\xfe{\x01", 5)},
      {"overflow", R"({"camera": {"vpd": 1e999}})"},
      {"twice", R"({"camera": {"vpd": 1, "vpd": 2}})"},
      {"unknownkey", R"({"cameras": 1})"},
      {"shape", R"({"camera": {"n": [1, 2]}})"},
      {"truncated", R"({"camera": {"n": [1, )"},
      {"text", "I did not do the homework."},
      {"array", "[1, 2, 3]"},
  };
  // A value of the wrong shape or an unknown key is graded, not refused (issue 38): wrong, or warned about.
  for (const auto& [id, text] : hostile)
    write(id + ".json", text), expected[id] = id == "shape" || id == "unknownkey" ? "fail" : "error";
  ASSERT_EQ(::mkfifo((dir_ / "class" / "fifo.json").c_str(), 0600), 0);
  expected["fifo"] = "error";
  fs::create_symlink("/dev/zero", dir_ / "class" / "zero.json");
  expected["zero"] = "error";
  fs::create_directories(dir_ / "class" / "not-a-student");  // folders are not answers
  ASSERT_EQ(expected.size(), 300u);

  const test::ProcessResult r = vplab("grade batch --assignment sheet/assignment.json --answers class --out out --jobs 2");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("300 answers in"));
  EXPECT_THAT(r.err, HasSubstr("300/300 graded"));
  const auto rows = csvRows(readFile(dir_ / "out" / "grades.csv"));
  ASSERT_EQ(rows.size(), 300u);
  for (const auto& [id, outcome] : expected) {
    SCOPED_TRACE(id);
    ASSERT_TRUE(rows.count(id));
    const std::vector<std::string>& row = rows.at(id);
    ASSERT_GE(row.size(), 5u + a.items.size());
    EXPECT_EQ(row[3], outcome == "pass" ? "yes" : "no");
    EXPECT_EQ(!row[4].empty(), outcome == "error") << row[4];
    if (outcome == "pass") {
      EXPECT_EQ(std::stod(row[1]), maxPoints);
    } else if (outcome == "fail") {
      EXPECT_LT(std::stod(row[1]), maxPoints);
    }
    EXPECT_TRUE(fs::exists(dir_ / "out" / "reports" / (id + ".xml")));
    EXPECT_TRUE(fs::exists(dir_ / "out" / "reports" / (id + ".txt")));
  }
  EXPECT_THAT(rows.at("fifo")[4], HasSubstr("must be a regular file"));
  EXPECT_THAT(rows.at("deep")[4], HasSubstr("nested deeper"));
  EXPECT_EQ(rows.at("empty0")[1], "0");
  // JUnit: the student's id as classname, a time; results.json in the platforms' form.
  const std::string xml = readFile(dir_ / "out" / "reports" / "transposed0.xml");
  EXPECT_THAT(xml, HasSubstr("classname=\"transposed0\""));
  EXPECT_THAT(xml, HasSubstr(" time=\""));
  const Json results = Json::parse(readFile(dir_ / "out" / "results.json"));
  ASSERT_EQ(results["students"].size(), 300u);
  const Json& first = results["students"][0];
  for (const char* key : {"id", "score", "max_score", "execution_time", "output", "tests"}) EXPECT_TRUE(first.contains(key)) << key;
}

TEST_F(GradeBatch, WhatStopsTheWholeBatchIsAnErrorNamingIt) {
  auto r = vplab("grade batch --answers .");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("--assignment FILE is required"));
  std::ofstream(dir_ / "a.json") << R"({"vplab_assignment": 1, "scene": "missing.json", "items": [{"path": "/camera/n"}]})";
  r = vplab("grade batch --assignment a.json --answers .");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("missing.json"));
  r = vplab("grade batch --assignment a.json --answers nowhere --jobs 0");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("--jobs \"0\""));
}

}  // namespace
}  // namespace vplab
