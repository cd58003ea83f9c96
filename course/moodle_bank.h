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
//   {1:NUMERICAL:=0.6:0.001#Right~%0%-0.6:0.001#Mistake: … (where to read)~%0%*#Wrong}
//
// weight 1 per value (a matrix counts its 16 values, as the grader does); `=` the key's value with
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
#include "pipeline/language.h"

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
/// GradingReference::models) predict for it beyond the tolerance.
std::vector<ClozeValue> clozeValues(const Assignment& assignment, const nlohmann::ordered_json& key,
                                    const std::vector<std::pair<Mistake, nlohmann::ordered_json>>& models,
                                    Language lang);

/// A number as Moodle's NUMBER_REGEX reads it (shortest round-trip form; -0 as 0). Throws
/// vplab::Error for a number that is not finite.
std::string clozeNumber(double x);
/// Text for a sub-question's feedback, escaped as above.
std::string clozeFeedbackText(std::string_view text);
/// The sub-question of one value: "{1:NUMERICAL:=…}".
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
