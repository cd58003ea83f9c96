// The fields a student fills in for an exercise's items (issue 40): each item of the assignment
// (course/assignment.h) shaped as its value in the answer format is (course/exercise_answer.h): a
// number, a vector, a 4 × 4 matrix, an outcode's six bits, or a polygon (a list of vertices whose
// length is part of the answer). The texts are kept as typed: the answer written from them is what
// the grader reads (a fraction "-3/5", a decimal comma "0,6", an outcode "100010", as on paper and in
// the Moodle quiz), so Check, `vplab grade numbers` and the quiz see the same characters.
#pragma once

#include "course/assignment.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace vplab {

enum class FieldKind { number, vector, matrix, outcode, polygon };

/// The most vertices a polygon's field takes: a convex polygon clipped by six planes gains at most
/// six, and the exercises' polygons have at most five.
inline constexpr int kMaxPolygonVertices = 16;
/// The longest text a field keeps (the grader reads at most 40 characters of a number).
inline constexpr size_t kMaxFieldText = 40;

struct ItemFields {
  AssignmentItem item;  // its path, title and points
  FieldKind kind = FieldKind::number;
  int rows = 1;     // a matrix's rows, a polygon's vertices (changed by the student), else 1
  int columns = 1;  // a vector's length, a matrix's columns, a polygon's vertex size, else 1
  std::vector<std::string> texts;  // rows × columns, row by row

  std::string& text(int row, int column) { return texts[size_t(row * columns + column)]; }
  const std::string& text(int row, int column) const { return texts[size_t(row * columns + column)]; }
  /// Whether the student typed anything into it.
  bool answered() const;
  /// A polygon's vertex count, kept within 0 … kMaxPolygonVertices; other kinds keep theirs.
  void setRows(int n);
  /// The JSON pointer of one field's value in the answer: the item's path, then the row and the
  /// column as the value's shape has them ("/matrices/vrc_from_wc/1/3", "/camera/n/2").
  std::string path(int row, int column) const;
};

/// Each item's fields, empty, in the assignment's order, shaped as `key`'s value at the item's path
/// (the answer key, course/exercise_answer.h). A polygon starts with no vertex: how many it has is
/// part of the answer. Throws vplab::Error for an item the key has no value for.
std::vector<ItemFields> answerFields(const Assignment& assignment, const nlohmann::ordered_json& key);

/// A typed text as the answer keeps it: blanks taken out, the typographic minus (U+2212) and the
/// dash (U+2013) read as '-', at most kMaxFieldText characters. Empty: not answered.
std::string normalizedField(std::string_view typed);
/// Whether the grader reads `text` as a value of `kind` (a number: a decimal with point or comma, a
/// fraction; an outcode: six bits or a whole number 0 … 63). Empty text is readable (not answered).
bool readableField(FieldKind kind, std::string_view text);

/// The answer file of the fields (answer.json, as `vplab grade numbers` and `grade batch` read it):
/// `answerTemplate` with each item's value in place, null where nothing was typed; each text as the
/// student typed it (normalized).
nlohmann::ordered_json answerOfFields(const std::vector<ItemFields>& fields, const nlohmann::ordered_json& answerTemplate);

/// Fills the fields from an answer (a kept one, the folder's answer.json): numbers written as
/// they were (strings) or as JSON numbers print. Values of another shape are left out. Returns how
/// many fields were filled.
size_t fillFields(std::vector<ItemFields>& fields, const nlohmann::ordered_json& answer);

}  // namespace vplab
