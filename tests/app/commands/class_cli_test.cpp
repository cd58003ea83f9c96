// Issue 38, parts 3 and 4: `vplab exercise --roster --moodle` and `vplab grade batch --exercises`, the
// round trip of a Moodle class: the grading worksheet in, one variant per student, Moodle's
// "Download all submissions" layout graded against each student's own variant, and the worksheet and
// feedback zip out. Oracles: the files each student was given (their own solution.json, another
// student's), the worksheet's own rows, Python's zipfile reading the zip.
#include "course/roster.h"
#include "tests/support/files.h"
#include "tests/support/process.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::readFile;
using test::shellQuoted;

class ClassCli : public test::ProcessTest {
 protected:
  test::ProcessResult vplab(const std::string& args) { return sh(shellQuoted(VPLAB_EXE) + " " + args); }
};

const std::string kWorksheet =
    "\xEF\xBB\xBFIdentifier,\"Full name\",\"Email address\",Status,Grade,\"Maximum Grade\",\"Grade can be changed\","
    "\"Last modified (submission)\",\"Last modified (grade)\",\"Feedback comments\"\r\n"
    "\"Participant 101\",\"Müller, Anna\",anna@uni.de,\"Submitted for grading\",,15.00,Yes,-,-,\r\n"
    "\"Participant 7\",\"Bob Bau\",bob@uni.de,\"Submitted for grading\",,15.00,Yes,-,-,\r\n"
    "\"Participant 12\",\"Cem Can\",cem@uni.de,\"No submission\",,15.00,Yes,-,-,\r\n";

TEST_F(ClassCli, AMoodleClassRoundTrips) {
  std::ofstream(dir_ / "worksheet.csv", std::ios::binary) << kWorksheet;
  auto r = vplab("exercise --seed 3 --topic orientation --roster worksheet.csv --moodle bank.xml --out week");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* id : {"101", "7", "12"}) {
    EXPECT_TRUE(fs::exists(dir_ / "week/students" / id / "sheet.md")) << id;
    EXPECT_TRUE(fs::exists(dir_ / "week/students" / id / "answer.json")) << id;
    EXPECT_TRUE(fs::exists(dir_ / "week/students" / id / "exercise.json")) << id;  // it opens in the viewer (issue 40)
    EXPECT_FALSE(fs::exists(dir_ / "week/students" / id / "solution.json")) << id;  // the key stays with the staff
    EXPECT_TRUE(fs::exists(dir_ / "week/staff" / id / "solution.json")) << id;
    EXPECT_TRUE(fs::exists(dir_ / "week/staff" / id / "assignment.json")) << id;
  }
  // Each student their own variant.
  EXPECT_NE(readFile(dir_ / "week/staff/101/solution.json"), readFile(dir_ / "week/staff/7/solution.json"));
  const std::string bank = readFile(dir_ / "bank.xml");
  EXPECT_THAT(bank, HasSubstr("<question type=\"category\">"));
  size_t clozes = 0;
  for (size_t at = 0; (at = bank.find("<question type=\"cloze\">", at)) != std::string::npos; ++at) ++clozes;
  EXPECT_EQ(clozes, 3u);
  EXPECT_EQ(sh("python3 -c \"import xml.dom.minidom as m; m.parse('bank.xml')\"").exitCode, 0);

  // Moodle's "Download all submissions": Anna hands in her own key, Bob Anna's (another variant), Cem
  // nothing; a stray file, a folder of another layout and a link are not matched.
  const fs::path subs = dir_ / "subs";
  fs::create_directories(subs / "Müller, Anna_101_assignsubmission_file_");
  fs::create_directories(subs / "Bob Bau_7_assignsubmission_file_");
  fs::create_directories(subs / "random folder");
  fs::copy_file(dir_ / "week/staff/101/solution.json", subs / "Müller, Anna_101_assignsubmission_file_/answer.json");
  fs::copy_file(dir_ / "week/staff/101/solution.json", subs / "Bob Bau_7_assignsubmission_file_/mine.json");
  std::ofstream(subs / "stray.json") << "{}";
  fs::create_symlink("/etc/passwd", subs / "7.json");
  r = vplab("grade batch --exercises week --answers subs --out grades");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("not matched: stray.json"));
  EXPECT_THAT(r.out, HasSubstr("not matched: 7.json: a link (not followed)"));
  EXPECT_THAT(r.out, HasSubstr("not matched: random folder/"));

  const CsvTable sheet = parseCsv(readFile(dir_ / "grades/moodle-grading-worksheet.csv"), "worksheet");
  const CsvTable given = parseCsv(kWorksheet, "given");
  EXPECT_EQ(sheet.header, given.header);
  ASSERT_EQ(sheet.rows.size(), 3u);
  EXPECT_EQ(sheet.rows[0][4], "10.00");  // Anna: all right (the orientation sheet: 10 points)
  EXPECT_THAT(sheet.rows[1][9], HasSubstr("another student's variant (101)"));
  EXPECT_THAT(readFile(dir_ / "grades/reports/7.txt"), HasSubstr("those of the variant of 101"));
  EXPECT_THAT(readFile(dir_ / "grades/reports/7.json"), HasSubstr("\"other_variant\": \"101\""));
  EXPECT_NE(sheet.rows[1][4], "10.00");
  EXPECT_EQ(sheet.rows[2][4], "0.00");
  EXPECT_EQ(sheet.rows[2][9], "No submission.");
  for (size_t i = 0; i < 3; ++i)
    for (size_t c : {0, 1, 2, 3, 5, 6, 7, 8}) EXPECT_EQ(sheet.rows[i][c], given.rows[i][c]) << i << "," << c;

  // The feedback zip in Moodle's layout, read by Python's zipfile (CRCs checked by testzip).
  r = sh("python3 -c \"import zipfile; z = zipfile.ZipFile('grades/moodle-feedback-files.zip'); "
         "assert z.testzip() is None; print('\\n'.join(z.namelist()))\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out,
            "Müller, Anna_101_assignsubmission_file_/report.md\nBob Bau_7_assignsubmission_file_/report.md\n"
            "Cem Can_12_assignsubmission_file_/report.md\n");
}

TEST_F(ClassCli, TheSubmissionsZipIsReadAsMoodleDownloadsIt) {
  std::ofstream(dir_ / "worksheet.csv", std::ios::binary) << kWorksheet;
  ASSERT_EQ(vplab("exercise --seed 2 --topic orientation --roster worksheet.csv --out week").exitCode, 0);
  // Deflated by Python's zipfile, with an entry that climbs out and one far too large (a zip bomb's header).
  auto r = sh("python3 -c \"import zipfile; z = zipfile.ZipFile('subs.zip', 'w', zipfile.ZIP_DEFLATED); "
              "z.write('week/staff/7/solution.json', 'Bob Bau_7_assignsubmission_file_/answer.json'); "
              "z.writestr('../../evil.json', '{}'); z.writestr('x/y/z.txt', 'hi'); "
              "z.writestr('Cem Can_12_assignsubmission_file_/notes.txt', 'hi'); z.close()\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = vplab("grade batch --exercises week --answers subs.zip --out grades");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("not matched: ../../evil.json"));
  EXPECT_THAT(r.out, HasSubstr("not matched: x/y/z.txt"));
  EXPECT_THAT(r.out, HasSubstr("not matched: Cem Can_12_assignsubmission_file_/: no .json file"));
  EXPECT_FALSE(fs::exists(dir_ / ".." / "evil.json"));
  const CsvTable sheet = parseCsv(readFile(dir_ / "grades/moodle-grading-worksheet.csv"), "worksheet");
  ASSERT_EQ(sheet.rows.size(), 3u);
  EXPECT_EQ(sheet.rows[1][4], "10.00");  // Bob, from the zip: his own key
  EXPECT_EQ(sheet.rows[0][9], "No submission.");
  std::ofstream(dir_ / "bad.zip") << "PK not really";
  r = vplab("grade batch --exercises week --answers bad.zip --out g2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("bad.zip: not a zip archive"));
}

TEST_F(ClassCli, BadRostersAndFoldersAreUsageErrorsNamingThem) {
  std::ofstream(dir_ / "r.csv") << "id\nalice\n../evil\n";
  auto r = vplab("exercise --roster r.csv --out x");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("r.csv: line 3: id \"../evil\""));
  EXPECT_FALSE(fs::exists(dir_ / "x"));
  r = vplab("exercise --roster r.csv --student-id a --out x");
  EXPECT_EQ(r.exitCode, 2);
  r = vplab("grade batch --exercises nowhere --answers .");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_THAT(r.err, HasSubstr("nowhere/roster.csv"));
}

}  // namespace
}  // namespace vplab
