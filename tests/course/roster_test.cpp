// Issue 38: a class roster (a CSV with an id column, or Moodle's grading worksheet), the worksheet
// written back for Moodle, the submission folders of Moodle's "Download all submissions", and the
// stored zip of the feedback files. Oracles: hand-written CSV and zip bytes, and a reader of the
// zip format written here from PKWARE's APPNOTE (not the writer's code).
#include "course/exercise.h"
#include "course/roster.h"
#include "course/zip_archive.h"
#include "base/error.h"
#include "tests/support/test_util.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>

namespace vplab {
namespace {

using ::testing::HasSubstr;
using test::errorOf;

// Moodle's worksheet as downloaded (a BOM, CRLF, quoted names with commas and quotes).
const std::string kWorksheet =
    "\xEF\xBB\xBFIdentifier,\"Full name\",\"Email address\",Status,Grade,\"Maximum Grade\",\"Grade can be changed\","
    "\"Last modified (submission)\",\"Last modified (grade)\",\"Feedback comments\"\r\n"
    "\"Participant 101\",\"Müller, Anna\",anna@uni.de,\"Submitted for grading\",,15.00,Yes,\"Monday, 3 June 2024, 10:00 AM\",-,\r\n"
    "\"Participant 7\",\"Bob \"\"The Builder\"\"\",bob@uni.de,\"No submission\",,15.00,Yes,-,-,\r\n";

TEST(Roster, ReadsMoodlesGradingWorksheetByParticipantNumber) {
  const Roster r = parseRoster(kWorksheet, "worksheet.csv");
  EXPECT_TRUE(r.moodle);
  ASSERT_EQ(r.students.size(), 2u);
  EXPECT_EQ(r.students[0].id, "101");
  EXPECT_EQ(r.students[0].fullName, "Müller, Anna");
  EXPECT_EQ(r.students[1].id, "7");
  EXPECT_EQ(r.students[1].fullName, "Bob \"The Builder\"");
  EXPECT_EQ(r.table.header.at(0), "Identifier");  // the BOM is not part of the name
}

TEST(Roster, ReadsAGermanMoodlesWorksheet) {
  const std::string de =
      "ID,Vollständiger Name,E-Mail-Adresse,Status,Bewertung,Bestwertung,Bewertung kann geändert werden,"
      "Zuletzt geändert (Abgabe),Zuletzt geändert (Bewertung),Feedback als Kommentar\n"
      "Teilnehmer/in1327670,Anna Müller,anna@uni.de,Keine Abgabe,,15,Ja,-,-,\n";
  const Roster r = parseRoster(de, "bewertungen.csv");
  EXPECT_TRUE(r.moodle);
  ASSERT_EQ(r.students.size(), 1u);
  EXPECT_EQ(r.students[0].id, "1327670");
  EXPECT_EQ(r.students[0].fullName, "Anna Müller");
  const CsvTable t = parseCsv(moodleWorksheet(r, {{"1327670", 7, "gut"}}, 15), "out");
  EXPECT_EQ(t.header, r.table.header);
  EXPECT_EQ(t.rows[0][4], "7.00");
  EXPECT_EQ(t.rows[0][9], "gut");
  EXPECT_EQ(t.rows[0][0], "Teilnehmer/in1327670");
}

TEST(Roster, ReadsACsvWithAnIdColumnAndKeepsTheOtherColumns) {
  const Roster r = parseRoster("name,id,group\nAlice,alice,A\n\nBob,b.ob-2@x,B\n", "class.csv");
  EXPECT_FALSE(r.moodle);
  ASSERT_EQ(r.students.size(), 2u);
  EXPECT_EQ(r.students[1].id, "b.ob-2@x");
  EXPECT_EQ(r.table.rows[1][2], "B");
}

TEST(Roster, BadRostersAreErrorsNamingTheLineAndTheValue) {
  EXPECT_THAT(errorOf([] { parseRoster("name\nAlice\n", "r.csv"); }), HasSubstr("no \"id\" column"));
  EXPECT_THAT(errorOf([] { parseRoster("id\n../etc\n", "r.csv"); }), HasSubstr("line 2: id \"../etc\""));
  EXPECT_THAT(errorOf([] { parseRoster("id\na b\n", "r.csv"); }), HasSubstr("id \"a b\""));
  EXPECT_THAT(errorOf([] { parseRoster("id\nalice\nalice\n", "r.csv"); }), HasSubstr("line 3: id \"alice\" is given twice"));
  EXPECT_THAT(errorOf([] { parseRoster("id,name\nalice\n", "r.csv"); }), HasSubstr("row 2 has 1 fields where the header has 2"));
  EXPECT_THAT(errorOf([] { parseRoster("id\n\"alice\n", "r.csv"); }), HasSubstr("line 2: a quoted field is not closed"));
  EXPECT_THAT(errorOf([] { parseRoster("id\n\"alice\"x\n", "r.csv"); }), HasSubstr("text after a closing quote"));
  EXPECT_THAT(errorOf([] { parseRoster("Identifier\nStudent\n", "r.csv"); }), HasSubstr("\"Participant N\" expected"));
  EXPECT_THAT(errorOf([] { parseRoster("id\n", "r.csv"); }), HasSubstr("no students"));
  EXPECT_THAT(errorOf([] { parseRoster("", "r.csv"); }), HasSubstr("empty"));
  std::string huge = "id\n";
  for (size_t i = 0; i <= kMaxRosterRows + 1; ++i) huge += "s" + std::to_string(i) + "\n";
  EXPECT_THAT(errorOf([&] { parseRoster(huge, "r.csv"); }), HasSubstr("more than 20000 rows"));
}

TEST(Roster, TheWorksheetKeepsMoodlesHeaderAndRowsAndFillsGradeAndFeedback) {
  const Roster r = parseRoster(kWorksheet, "worksheet.csv");
  const std::string out = moodleWorksheet(r, {{"7", 12.5, "12.5 of 15 points, see report.md"}}, 15);
  const CsvTable t = parseCsv(out, "out.csv");
  EXPECT_EQ(t.header, r.table.header);
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], r.table.rows[0]);  // no grade for 101: the row as it came
  EXPECT_EQ(t.rows[1][0], "Participant 7");
  EXPECT_EQ(t.rows[1][1], "Bob \"The Builder\"");
  EXPECT_EQ(t.rows[1][4], "12.50");
  EXPECT_EQ(t.rows[1][9], "12.5 of 15 points, see report.md");
  EXPECT_THAT(out, HasSubstr("\r\n"));
}

TEST(Roster, ACsvRostersWorksheetHasMoodlesColumns) {
  const Roster r = parseRoster("id,name\nalice,Alice\n", "r.csv");
  const CsvTable t = parseCsv(moodleWorksheet(r, {{"alice", 3, "ok"}}, 15), "w.csv");
  EXPECT_EQ(t.header, (std::vector<std::string>{"Identifier", "Full name", "Email address", "Status", "Grade",
                                                "Maximum Grade", "Grade can be changed", "Last modified (submission)",
                                                "Last modified (grade)", "Feedback comments"}));
  EXPECT_EQ(t.rows.at(0).at(0), "Participant 1");
  EXPECT_EQ(t.rows.at(0).at(4), "3.00");
}

TEST(Roster, SubmissionFoldersNameTheParticipant) {
  EXPECT_EQ(participantOfFolder("Anna Müller_101_assignsubmission_file_"), "101");
  EXPECT_EQ(participantOfFolder("A_B_C_7_assignsubmission_onlinetext_"), "7");
  EXPECT_EQ(participantOfFolder("Anna_101_assignsubmission_file"), std::nullopt);
  EXPECT_EQ(participantOfFolder("_assignsubmission_file_"), std::nullopt);
  EXPECT_EQ(participantOfFolder("x_.._assignsubmission_file_"), std::nullopt);
}

// ------------------------------------------------------------------ the zip, read back by APPNOTE

uint32_t get(const std::string& s, size_t at, int bytes) {
  uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(s.at(at + size_t(i)));
  return v;
}

uint32_t crc32Of(const std::string& data) {  // the bitwise CRC-32 of the zip format (polynomial 0xEDB88320)
  uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : data) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

TEST(ZipArchive, StoredEntriesReadBackThroughTheCentralDirectory) {
  const std::vector<std::pair<std::string, std::string>> entries = {
      {"Anna Müller_101_assignsubmission_file_/report.md", "# 15 of 15\n"}, {"b/empty.txt", ""}};
  const std::string zip = storedZip(entries);
  // The end record: the last 22 bytes.
  const size_t end = zip.size() - 22;
  ASSERT_EQ(get(zip, end, 4), 0x06054b50u);
  ASSERT_EQ(get(zip, end + 10, 2), 2u);
  size_t at = get(zip, end + 16, 4);
  for (const auto& [name, data] : entries) {
    ASSERT_EQ(get(zip, at, 4), 0x02014b50u);
    const uint32_t crc = get(zip, at + 16, 4), size = get(zip, at + 24, 4), nameLen = get(zip, at + 28, 2);
    const uint32_t local = get(zip, at + 42, 4);
    EXPECT_EQ(get(zip, at + 10, 2), 0u);  // stored
    EXPECT_EQ(zip.substr(at + 46, nameLen), name);
    EXPECT_EQ(crc, crc32Of(data));
    EXPECT_EQ(size, data.size());
    ASSERT_EQ(get(zip, local, 4), 0x04034b50u);
    const uint32_t localName = get(zip, local + 26, 2), extra = get(zip, local + 28, 2);
    EXPECT_EQ(zip.substr(local + 30 + localName + extra, size), data);
    at += 46 + nameLen;
  }
  EXPECT_EQ(crc32Of("123456789"), 0xCBF43926u);  // the check value of CRC-32
}

TEST(ZipArchive, ReadsBackWhatItWroteAndRejectsDamageAndHugeEntries) {
  const std::string zip = storedZip({{"a_1_assignsubmission_file_/answer.json", "{\"x\": 1}"}, {"notes.txt", "hi"}, {"e", ""}});
  auto all = [](const std::string&) { return true; };
  const std::vector<ZipEntry> entries = readZip(zip, "s.zip", 1000, all);
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].name, "a_1_assignsubmission_file_/answer.json");
  EXPECT_EQ(entries[0].data, "{\"x\": 1}");
  EXPECT_EQ(entries[2].data, "");
  // Only the wanted entries' data are read.
  EXPECT_EQ(readZip(zip, "s.zip", 1000, [](const std::string& n) { return n == "e"; })[1].data, "");
  // An entry larger than the limit, by its header, before anything is read.
  EXPECT_THAT(errorOf([&] { readZip(zip, "s.zip", 4, all); }), HasSubstr("exceed the limit of 4"));
  // A flipped byte of the data: its CRC-32 no longer matches.
  std::string damaged = zip;
  damaged[damaged.find("{\"x\"") + 1] = 'y';
  EXPECT_THAT(errorOf([&] { readZip(damaged, "s.zip", 1000, all); }), HasSubstr("CRC-32 mismatch"));
  EXPECT_THAT(errorOf([&] { readZip("PK", "s.zip", 1000, all); }), HasSubstr("not a zip archive"));
  EXPECT_THAT(errorOf([&] { readZip(std::string(100, 'x'), "s.zip", 1000, all); }), HasSubstr("no end of central directory"));
  std::string truncated = zip.substr(0, 20) + zip.substr(zip.size() - 22);
  EXPECT_THAT(errorOf([&] { readZip(truncated, "s.zip", 1000, all); }), HasSubstr("damaged"));
}

TEST(ZipArchive, RejectsNamesThatLeaveTheArchive) {
  for (const char* bad : {"../x", "/abs", "a/../b", "a\\b", "", "a//b"})
    EXPECT_THAT(errorOf([&] { storedZip({{bad, "x"}}); }), HasSubstr("not a plain relative path")) << bad;
}

}  // namespace
}  // namespace vplab
