#include "course/roster.h"

#include "base/error.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>

namespace vplab {

namespace {

[[noreturn]] void fail(std::string_view source, size_t line, const std::string& what) {
  throw Error(std::string(source) + ": line " + std::to_string(line) + ": " + what);
}

std::string trimmed(std::string_view s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The column whose (trimmed, case-insensitive) name is one of `names`.
std::optional<size_t> columnOf(const std::vector<std::string>& header, const std::vector<std::string_view>& names) {
  for (size_t i = 0; i < header.size(); ++i)
    for (std::string_view n : names)
      if (lower(trimmed(header[i])) == lower(std::string(n))) return i;
  return std::nullopt;
}

// Moodle's column names in English and German. A German Moodle's worksheet begins
// "ID,Vollständiger Name,E-Mail-Adresse,Status,…,Bewertung,Bestwertung,…,Feedback als Kommentar" with
// identifiers "Teilnehmer/in1327670" (seen in public tools that read and write it).
const std::vector<std::string_view> kIdentifier = {"Identifier"};
const std::vector<std::string_view> kFullName = {"Full name", "Vollständiger Name", "name"};
const std::vector<std::string_view> kGrade = {"Grade", "Bewertung"};
const std::vector<std::string_view> kFeedback = {"Feedback comments", "Feedback als Kommentar"};

/// "Participant 12" (English), "Teilnehmer/in12" (German): a word without digits, then the number → "12".
std::optional<std::string> participantNumber(std::string_view identifier) {
  const std::string s = trimmed(identifier);
  size_t digits = s.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(s[digits - 1]))) --digits;
  if (digits == s.size() || s.size() - digits > 12 || digits == 0) return std::nullopt;
  if (std::any_of(s.begin(), s.begin() + long(digits), [](unsigned char c) { return std::isdigit(c); })) return std::nullopt;
  return s.substr(digits);
}

std::string gradeText(double g) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", g);
  return buf;
}

}  // namespace

CsvTable parseCsv(std::string_view text, std::string_view source) {
  if (text.size() > kMaxRosterBytes)
    throw Error(std::string(source) + ": " + std::to_string(text.size()) + " bytes exceed the limit of " +
                std::to_string(kMaxRosterBytes) + " for a roster");
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> record;
  std::string field;
  size_t line = 1, recordLine = 1;
  size_t i = 0;
  auto endRecord = [&] {
    record.push_back(std::move(field));
    field.clear();
    // A blank line (one empty field) is no record.
    if (!(record.size() == 1 && record[0].empty())) {
      if (records.size() > kMaxRosterRows) fail(source, recordLine, "more than " + std::to_string(kMaxRosterRows) + " rows");
      records.push_back(std::move(record));
    }
    record.clear();
  };
  while (i < text.size()) {
    const char c = text[i];
    if (c == '"' && field.empty()) {
      const size_t start = line;
      ++i;
      for (;;) {
        if (i >= text.size()) fail(source, start, "a quoted field is not closed");
        if (text[i] == '"') {
          if (i + 1 < text.size() && text[i + 1] == '"') {
            field += '"', i += 2;
            continue;
          }
          ++i;
          break;
        }
        if (text[i] == '\n') ++line;
        field += text[i++];
      }
      if (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r')
        fail(source, line, "text after a closing quote (\"" + std::string(text.substr(i, 10)) + "\")");
      if (field.empty()) field = std::string();  // "" is an empty field
      continue;
    }
    if (c == ',') {
      record.push_back(std::move(field));
      field.clear();
      ++i;
    } else if (c == '\r' || c == '\n') {
      endRecord();
      i += c == '\r' && i + 1 < text.size() && text[i + 1] == '\n' ? 2 : 1;
      recordLine = ++line;
    } else {
      field += c;
      ++i;
    }
  }
  if (!field.empty() || !record.empty()) endRecord();
  if (records.empty()) throw Error(std::string(source) + ": empty: a header row and one row per student expected");
  CsvTable t;
  t.header = std::move(records[0]);
  for (size_t r = 1; r < records.size(); ++r) {
    if (records[r].size() != t.header.size())
      throw Error(std::string(source) + ": row " + std::to_string(r + 1) + " has " + std::to_string(records[r].size()) +
                  " fields where the header has " + std::to_string(t.header.size()));
    t.rows.push_back(std::move(records[r]));
  }
  return t;
}

std::string csvField(std::string_view f) {
  if (f.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(f);
  std::string q = "\"";
  for (char c : f) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string csvRow(const std::vector<std::string>& fields) {
  std::string out;
  for (size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + csvField(fields[i]);
  return out + "\r\n";
}

bool validStudentId(std::string_view id) {
  if (id.empty() || id.size() > 64 || id == "." || id == "..") return false;
  return std::all_of(id.begin(), id.end(), [](unsigned char c) { return std::isalnum(c) || c == '.' || c == '-' || c == '@'; });
}

Roster parseRoster(std::string_view text, std::string_view source) {
  Roster r;
  r.table = parseCsv(text, source);
  const std::vector<std::string>& h = r.table.header;
  const auto identifier = columnOf(h, kIdentifier);
  const auto idColumn = columnOf(h, {"id"});
  // A German worksheet's identifier column is "ID": Moodle's when its first value is a participant's.
  r.moodle = identifier.has_value() ||
             (idColumn && !r.table.rows.empty() && participantNumber(r.table.rows[0][*idColumn]) &&
              !validStudentId(trimmed(r.table.rows[0][*idColumn])));
  const auto moodleColumn = identifier ? identifier : idColumn;
  if (!r.moodle && !idColumn)
    throw Error(std::string(source) + ": no \"id\" column and no \"Identifier\" column (Moodle's grading worksheet); "
                "the header is: " + csvRow(h).substr(0, 200));
  const auto name = columnOf(h, kFullName);
  std::set<std::string> seen;
  for (size_t i = 0; i < r.table.rows.size(); ++i) {
    const std::vector<std::string>& row = r.table.rows[i];
    RosterStudent s;
    s.row = i;
    if (name) s.fullName = trimmed(row[*name]);
    if (r.moodle) {
      const auto n = participantNumber(row[*moodleColumn]);
      if (!n) fail(source, i + 2, "Identifier \"" + row[*moodleColumn] + "\": \"Participant N\" expected");
      s.id = *n;
    } else {
      s.id = trimmed(row[*idColumn]);
      if (!validStudentId(s.id))
        fail(source, i + 2, "id \"" + s.id + "\": 1 to 64 letters, digits, '.', '-' or '@' expected");
    }
    if (!seen.insert(s.id).second) fail(source, i + 2, "id \"" + s.id + "\" is given twice");
    r.students.push_back(std::move(s));
  }
  if (r.students.empty()) throw Error(std::string(source) + ": no students (only a header row)");
  return r;
}

std::optional<std::string> participantOfFolder(std::string_view folder) {
  for (std::string_view suffix : {"_assignsubmission_file_", "_assignsubmission_onlinetext_"}) {
    if (folder.size() <= suffix.size() || folder.substr(folder.size() - suffix.size()) != suffix) continue;
    const std::string_view rest = folder.substr(0, folder.size() - suffix.size());
    const size_t underscore = rest.rfind('_');
    if (underscore == std::string_view::npos) return std::nullopt;
    const std::string_view n = rest.substr(underscore + 1);
    if (!validStudentId(n)) return std::nullopt;
    return std::string(n);
  }
  return std::nullopt;
}

std::string moodleWorksheet(const Roster& roster, const std::vector<WorksheetGrade>& grades, double maxGrade) {
  auto gradeOf = [&](const std::string& id) -> const WorksheetGrade* {
    for (const WorksheetGrade& g : grades)
      if (g.id == id) return &g;
    return nullptr;
  };
  if (roster.moodle) {
    std::vector<std::string> header = roster.table.header;
    auto grade = columnOf(header, kGrade), feedback = columnOf(header, kFeedback);
    if (!grade) header.push_back("Grade"), grade = header.size() - 1;
    if (!feedback) header.push_back("Feedback comments"), feedback = header.size() - 1;
    std::string out = csvRow(header);
    for (const RosterStudent& s : roster.students) {
      std::vector<std::string> row = roster.table.rows[s.row];
      row.resize(header.size());
      if (const WorksheetGrade* g = gradeOf(s.id)) row[*grade] = gradeText(g->grade), row[*feedback] = g->feedback;
      out += csvRow(row);
    }
    return out;
  }
  // The column names from a table in read-only data: as an initializer list of strings, GCC stores
  // them as immediates ("Full nam" + "e"), which lintian's spelling check reads as a typo.
  static constexpr const char* kWorksheetColumns[] = {
      "Identifier", "Full name", "Email address", "Status", "Grade", "Maximum Grade", "Grade can be changed",
      "Last modified (submission)", "Last modified (grade)", "Feedback comments"};
  std::string out = csvRow(std::vector<std::string>(std::begin(kWorksheetColumns), std::end(kWorksheetColumns)));
  for (size_t k = 0; k < roster.students.size(); ++k) {
    const RosterStudent& s = roster.students[k];
    const WorksheetGrade* g = gradeOf(s.id);
    out += csvRow({"Participant " + std::to_string(k + 1), s.fullName.empty() ? s.id : s.fullName, "", "",
                   g ? gradeText(g->grade) : "", gradeText(maxGrade), "Yes", "", "", g ? g->feedback : ""});
  }
  return out;
}

}  // namespace vplab
