// A class roster (issue 38, part 3) and Moodle's grading worksheet (part 4), GL-free.
//
// CSV as RFC 4180 reads it: fields separated by commas, a field in double quotes may hold commas,
// line breaks and doubled quotes (""); lines end in CRLF or LF; a UTF-8 byte order mark (which
// Moodle's downloads begin with) is skipped.
//
// A roster is either
//   - a CSV with an `id` column (letters, digits, '.', '-', '@'; at most 64), other columns carried
//     through; or
//   - Moodle's grading worksheet as downloaded (Assignment ▸ "Download grading worksheet"): its rows
//     keyed by "Identifier" = "Participant N" (a German Moodle: "ID" = "Teilnehmer/inN"); the student's id is then N (Moodle's participant
//     number, which also names the student's folder in "Download all submissions":
//     "Full Name_N_assignsubmission_file_/").
// The worksheet's columns, as Moodle 3.x/4.x writes them in English (confirmed in public tools that
// read it, e.g. a MoodleGradingWorksheetAdapter listing "Identifier", "Full name", "Email address",
// "Status", "Grade", "Maximum Grade", "Grade can be changed", "Last modified (submission)",
// "Last modified (grade)", "Feedback comments"; sites add "ID number", "Group", … and a German site
// translates them: "ID", "Vollständiger Name", …, "Bewertung", …, "Feedback als Kommentar"): only the
// identifier, name, grade and feedback columns are looked for, by name in English or German;
// everything else is written back as it came.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // each as long as the header
};

/// The most rows (students) and bytes a roster may have (checked while reading).
inline constexpr size_t kMaxRosterRows = 20000;
inline constexpr size_t kMaxRosterBytes = size_t(16) << 20;

/// Parses CSV text. Throws vplab::Error "SOURCE: line L: …" for an unterminated quote, text after a
/// closing quote, a row with another number of fields than the header, an empty header name given
/// twice, or more than kMaxRosterRows rows.
CsvTable parseCsv(std::string_view text, std::string_view source);

/// One field as RFC 4180 writes it (quoted when it holds a comma, quote or line break).
std::string csvField(std::string_view field);
/// A row of fields, CRLF-terminated (as Moodle writes its worksheet).
std::string csvRow(const std::vector<std::string>& fields);

struct RosterStudent {
  std::string id;           // the id the variant is drawn for ("alice", or Moodle's participant number)
  std::string fullName;     // Moodle: "Full name"; a CSV: its "name" column, if any
  size_t row = 0;           // index into CsvTable::rows
};

struct Roster {
  CsvTable table;
  bool moodle = false;  // a Moodle grading worksheet
  std::vector<RosterStudent> students;
};

/// Reads a roster (see above). Throws vplab::Error naming the file, the line and the value: no `id`
/// or "Identifier" column, an id that is not valid, an "Identifier" that is not "Participant N",
/// an id given twice.
Roster parseRoster(std::string_view text, std::string_view source);

/// Whether `id` may name a student's variant and folder: 1 to 64 letters, digits, '.', '-' or '@',
/// not "." or "..".
bool validStudentId(std::string_view id);

/// Moodle's participant number in a folder name of "Download all submissions":
/// "Full Name_N_assignsubmission_file_" (also "_onlinetext_") → N; nullopt for another name. N is
/// Moodle's number; any valid student id (validStudentId) is taken, so that a CSV roster's ids work too.
std::optional<std::string> participantOfFolder(std::string_view folder);

/// A student's grade and feedback for the worksheet.
struct WorksheetGrade {
  std::string id;
  double grade = 0;
  std::string feedback;
};

/// The grading worksheet to upload ("Upload grading worksheet"): for a Moodle roster its own header
/// and rows with "Grade" and "Feedback comments" filled in (a column Moodle left out is added at the
/// end); for a CSV roster Moodle's English columns, the Identifier "Participant K" by the row's
/// position (K from 1), which the course must map itself. Grades are written with a '.' decimal point.
std::string moodleWorksheet(const Roster& roster, const std::vector<WorksheetGrade>& grades, double maxGrade);

}  // namespace vplab
