// No second implementation (issue 40): Check in the viewer and the page is `vplab grade numbers` of the
// answer Hand in writes. The same answer (the divide-first mistake model's, typed as text into the
// fields) is graded both ways, and the reports are compared whole.
#include "app/practice/practice.h"
#include "course/mistake_models.h"
#include "course/rational.h"
#include "tests/support/files.h"
#include "tests/support/process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;
using test::ProcessResult;
using test::shellQuoted;

class PracticeCli : public test::ProcessTest {
 protected:
  ProcessResult vplab(const std::string& args) { return sh(shellQuoted(VPLAB_EXE) + " " + args); }
};

std::string onPaper(double x) {
  if (const auto r = Rational::approximate(x)) return r->text();
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", x);
  return buf;
}

/// The fields filled with `answer`'s values as text, except the last item's (left empty: not given).
void typeAllButTheLast(Practice& p, const Json& answer) {
  for (size_t i = 0; i + 1 < p.fields.size(); ++i) {
    ItemFields& f = p.fields[i];
    const Json& v = answer[Json::json_pointer(f.item.path)];
    if (f.kind == FieldKind::polygon) f.setRows(int(v.size()));
    if (f.kind == FieldKind::outcode) f.texts[0] = std::to_string(v.get<int>());
    else if (f.kind == FieldKind::number) f.texts[0] = onPaper(v.get<double>());
    else if (f.kind == FieldKind::vector)
      for (int c = 0; c < f.columns; ++c) f.text(0, c) = onPaper(v[size_t(c)].get<double>());
    else
      for (int r = 0; r < f.rows; ++r)
        for (int c = 0; c < f.columns; ++c) f.text(r, c) = onPaper(v[size_t(r)][size_t(c)].get<double>());
  }
  ++p.edits;
}

/// The report without what names the files and the time taken.
Json comparable(Json report) {
  for (const char* key : {"student", "id", "scene", "seconds"}) report.erase(key);
  return report;
}

TEST_F(PracticeCli, CheckIsGradeNumbersOfTheHandedInAnswerForEveryReveal) {
  // The items' titles are the sheet's language's (assignment.json): the sheet is written in the language checked in.
  for (const auto& [topic, seed] : {std::pair{"clipping", 3}, std::pair{"pipeline", 4}}) {
    for (const Language lang : {Language::en, Language::de}) {
      const std::string language = lang == Language::de ? "de" : "en";
      const std::string folder = std::string(topic) + "-" + std::to_string(seed) + "-" + language;
      ASSERT_EQ(vplab("exercise --seed " + std::to_string(seed) + " --topic " + topic + " --lang " + language + " --out " + folder).exitCode, 0);
      for (const Reveal reveal : {Reveal::values, Reveal::stages, Reveal::none}) {
        Practice p = openPracticeFolder(dir_ / folder, reveal, lang);
        for (const auto& [id, dump] : p.grading.models)
          if (id == Mistake::divideFirst) typeAllButTheLast(p, dump);
        const PracticeCheck check = checkPractice(p, lang);
        test::TempDir out;
        const std::filesystem::path answer = out.path / "answer.json";
        {
          std::FILE* f = std::fopen(answer.c_str(), "w");
          ASSERT_NE(f, nullptr);
          const std::string text = practiceAnswer(p).dump(2);
          std::fwrite(text.data(), 1, text.size(), f);
          std::fclose(f);
        }
        const ProcessResult r = vplab("grade numbers --student " + shellQuoted(answer.string()) + " --assignment " + folder +
                                      "/assignment.json --json --reveal " + std::string(toString(reveal)) + " --lang " + language);
        ASSERT_TRUE(r.exitCode == 0 || r.exitCode == 1) << r.err;
        const Json cli = Json::parse(r.out);
        const std::string a = comparable(cli).dump(1), b = comparable(check.report.json).dump(1);
        EXPECT_EQ(a, b) << folder << " " << toString(reveal);
        if (a != b) {  // left for inspection with the test's directory
          std::FILE* f = std::fopen((dir_ / (folder + "-cli.json")).c_str(), "w");
          std::fputs(a.c_str(), f);
          std::fclose(f);
          f = std::fopen((dir_ / (folder + "-check.json")).c_str(), "w");
          std::fputs(b.c_str(), f);
          std::fclose(f);
        }
        EXPECT_EQ(r.exitCode == 0, check.report.passed);
      }
    }
  }
}

}  // namespace
}  // namespace vplab
