// A Moodle XML question bank of exercise sheets (issue 38, part 4): `vplab exercise … --moodle BANK.xml`.
// GL-free: the figures come in as PNG bytes.
//
// The format (Moodle XML, "Question bank ▸ Import ▸ Moodle XML format"):
//
//   <quiz>
//     <question type="category"><category><text>$course$/top/vplab/…</text></category></question>
//     <question type="cloze">                                one per variant (or per roster student)
//       <name><text>…</text></name>
//       <questiontext format="html"><text><![CDATA[ the sheet as HTML, figures as
//           <img src="@@PLUGINFILE@@/world.png">, then one sub-question per value of the answer key ]]></text>
//         <file name="world.png" path="/" encoding="base64">…</file></questiontext>
//       <generalfeedback format="html"><text></text></generalfeedback>
//       <penalty>0.3333333</penalty><hidden>0</hidden>
//     </question>
//   </quiz>
//
// A value's sub-question ("Embedded answers", qtype_multianswer):
//
//   {6:NUMERICAL:=0.6:0.001#Right~%0%-0.6:0.001#Mistake: … (where to read)~%0%*#Wrong}
//
// weighted so that each assignment item counts its points (clozeWeightFactor: a 2-point matrix's
// 16 values weigh as much together as two 1-point vectors' 3 values each); `=` the key's value with
// the assignment's tolerance made absolute, T · max(1, |value|) (course/grading.h's rule; integers
// such as outcodes exactly, tolerance 0; written with the fewest digits that stay within 1 % below
// it, never above); each mistake model's value (course/mistake_models.h, with
// the sheet's values, course/sheet_values.h) where it lies beyond that tolerance of the key, as a
// 0 % answer whose feedback names the mistake in the sheet's language (models predicting the same
// value share one answer); `*` any other number.
//
// Syntax as Moodle's parser reads it (moodle/moodle, question/type/multianswer/questiontype.php:
// ANSWER_START_REGEX `\{([0-9]*):(NUMERICAL|NM|…):`, ANSWER_ALTERNATIVE_FRACTION_REGEX
// `=|%(-?[0-9]+(?:[.,][0-9]*)?)%`, NUMERICAL_ALTERNATIVE_REGEX `^(NUMBER)(:NUMBER)?$` with NUMBER_REGEX
// `-?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)`; a feedback runs to the next `~` or `}` not
// preceded by a backslash and is then html_entity_decode'd, with `\}` → `}` and `\#` → `#`). So numbers
// are written plainly (no '+', no "inf"), and a feedback escapes `}` and `#` with a backslash, writes
// `~`, `{` and `\` as the character references &#126;, &#123; and &#92; (no backslash sequence turns back into
// them), and HTML's `&`, `<`, `>` twice (`&amp;lt;`: decoded once by the parser, once by the browser).
#pragma once

#include "course/assignment.h"
#include "course/mistake_models.h"
#include "base/language.h"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vplab {

/// A figure embedded in a question: `name` ("world.png", letters, digits, '.', '-', '_') and its PNG bytes.
struct MoodleFigure {
  std::string name;
  std::string png;
};

/// A wrong answer a mistake model predicts, and its feedback (plain text, escaped when written).
struct ClozeDistractor {
  double value = 0;
  std::string feedback;
};

/// One value of the answer key as a NUMERICAL sub-question.
struct ClozeValue {
  std::string path;   // JSON pointer into the answer: "/matrices/vrc_from_wc/1/3"
  std::string label;  // "vrcFromWc [2][4]" (indices from 1)
  double value = 0;
  double tolerance = 0;  // absolute
  std::vector<ClozeDistractor> mistakes;
  int weight = 1;        // the sub-question's weight, "{weight:NUMERICAL:…}" (clozeValues: its item's share)
  std::string item;      // the assignment item's path it belongs to (clozeValues), for the vertex order
};

/// One sheet (a variant) as a cloze question.
struct MoodleQuestion {
  std::string name;           // the question's name in the bank
  std::string sheetMarkdown;  // sheet.md of `vplab exercise` (figures referenced as NAME.svg)
  std::vector<MoodleFigure> figures;
  std::vector<ClozeValue> values;
  Language lang = Language::en;
};

/// The answer key's values (answerKey of course/exercise_answer.h), item by item in the assignment's
/// order, each with the mistakes `models` (mistake model, its answer with the sheet's values:
/// GradingReference::models) predict for it beyond the tolerance, and its weight (clozeWeightFactor):
/// an item's values weigh its points × the factor together. An item worth 0 points is not asked.
/// Throws vplab::Error for points that are no fraction with a denominator up to 1000.
std::vector<ClozeValue> clozeValues(const Assignment& assignment, const nlohmann::ordered_json& key,
                                    const std::vector<std::pair<Mistake, nlohmann::ordered_json>>& models,
                                    Language lang);

/// The factor F of the weights of clozeValues: each item's values weigh points × F together, so the
/// question's grade shares are the assignment's. Moodle's weights are integers (ANSWER_REGEX_NORM
/// `[0-9]*`), so F is the least integer for which every value of an item gets the same integer
/// weight points × F / (its number of values) (the least common multiple over the items of
/// values / gcd(values, points), points as fractions a/b: b·values / gcd(a, b·values)), as long as
/// that is at most kMaxEqualWeightFactor. Beyond (a clipping sheet whose polygons have 12, 16, 20,
/// 28 … values: their LCM grows fast, and Moodle stores a question's total, the sum of its weights,
/// as a number below 100 000), F is the least multiple of the points' denominators that gives every
/// value a weight of at least 1, and each item's points × F are spread over its values as evenly as
/// integers allow (weights differing by at most 1, the larger first): every item still counts
/// exactly its points. Counts are {item points, number of values}; 0 when no item has points.
inline constexpr int64_t kMaxEqualWeightFactor = 240;
int64_t clozeWeightFactor(const std::vector<std::pair<double, size_t>>& items);

/// Whether the item at `itemPath` is a clipped polygon ("…/clip_steps/N/polygon", "…/clipped_dc").
bool isPolygonItem(std::string_view itemPath);
/// The order a clipped polygon's vertices are asked in, as the bank states it once above the answers
/// of a sheet with polygons: Moodle grades value by value, so the student's vertex order must be the
/// key's, the order Sutherland–Hodgman writes them (pipeline/clipping.h, clipPolygonAgainstPlane;
/// the grader, course/grading.cpp, accepts any start and direction, a cloze question cannot).
std::string vertexOrderRule(Language lang);
/// The same for one polygon item, above its values (which vertex comes first, which way round); empty
/// for an item that is no clipped polygon.
std::string vertexOrderNote(std::string_view itemPath, Language lang);

/// A number as Moodle's NUMBER_REGEX reads it (shortest round-trip form; -0 as 0). Throws
/// vplab::Error for a number that is not finite.
std::string clozeNumber(double x);
/// Text for a sub-question's feedback, escaped as above.
std::string clozeFeedbackText(std::string_view text);
/// The sub-question of one value: "{weight:NUMERICAL:=…}".
std::string clozeSubquestion(const ClozeValue& value, Language lang);

/// The sheet's Markdown as HTML for Moodle: headings, lists, paragraphs, **bold**; math $…$ as
/// \(…\) and $$…$$ as \[…\] (MathJax's delimiters in Moodle's filter); a figure "![caption](world.svg)"
/// as <img src="@@PLUGINFILE@@/world.png">. Text is HTML-escaped.
std::string sheetHtml(std::string_view markdown);

/// The whole bank: a category question ("$course$/top/" + category), then the questions. Throws
/// vplab::Error for a figure name outside [A-Za-z0-9._-] or a question without values.
std::string moodleBankXml(std::string_view category, const std::vector<MoodleQuestion>& questions);

/// Base64 (RFC 4648, with padding), as Moodle XML embeds files.
std::string base64(std::string_view bytes);

}  // namespace vplab
