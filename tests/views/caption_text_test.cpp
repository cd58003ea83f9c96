// Captions (app/views/caption_text.h): inline mathematics as runs, and what a lecturer's typo leaves.
#include "app/views/caption_text.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

using Script = CaptionRun::Script;

TEST(CaptionText, MathBetweenDollarsWithScriptsAndCommands) {
  const std::vector<CaptionRun> runs = captionRuns("Then $z_{npc} \\to 1$ and $x^2 \\le w$.");
  const std::vector<CaptionRun> expected = {
      {"Then ", false, Script::normal}, {"z", true, Script::normal},     {"npc", true, Script::sub},
      {" → 1", true, Script::normal},   {" and ", false, Script::normal}, {"x", true, Script::normal},
      {"2", true, Script::super},       {" ≤ w", true, Script::normal},  {".", false, Script::normal}};
  EXPECT_EQ(runs, expected);
}

TEST(CaptionText, ACommandInAScriptAndAUnicodeLetterAsOneCharacter) {
  const std::vector<CaptionRun> runs = captionRuns("$t_\\alpha + t_φ + 2^{\\pi}$");
  ASSERT_EQ(runs.size(), 6u);
  EXPECT_EQ(runs[1], (CaptionRun{"α", true, Script::sub}));
  EXPECT_EQ(runs[3], (CaptionRun{"φ", true, Script::sub}));
  EXPECT_EQ(runs[5], (CaptionRun{"π", true, Script::super}));
}

TEST(CaptionText, NothingTheLecturerWroteDisappears) {
  // An unclosed $ is a dollar sign; an unknown command stays; an unclosed group runs to the end.
  EXPECT_EQ(captionPlainText("costs $5"), "costs $5");
  EXPECT_EQ(captionPlainText("$\\foo x$"), "\\foo x");
  EXPECT_EQ(captionPlainText("$a_{bc$"), "a_{bc}");
  EXPECT_EQ(captionPlainText("$x_$"), "x_");
  EXPECT_EQ(captionPlainText("$\\$"), "\\");
}

TEST(CaptionText, MarkdownEscapesAndMarksTheMath) {
  EXPECT_EQ(captionMarkdown("If $a<b$ & $z_{vrc}$"), "If <i>a&lt;b</i> &amp; <i>z<sub>vrc</sub></i>");
}

}  // namespace
}  // namespace vplab

namespace vplab {
namespace {

TEST(CaptionText, LinesBreakBetweenWordsAndAWordKeepsItsScripts) {
  // Every character 1 wide, scripts too; lines 10 wide, spaces 1.
  const CaptionMeasure widthOf = [](std::string_view text, CaptionRun::Script) { return double(text.size()); };
  int lines = 0;
  const std::vector<CaptionPiece> pieces = layOutCaption("one two three $z_{npc}$ end", 10, widthOf, 1, &lines);
  ASSERT_EQ(pieces.size(), 6u);
  EXPECT_EQ(pieces[0].text, "one");
  EXPECT_EQ(pieces[1].x, 4);  // "one two" fits in 10
  EXPECT_EQ(pieces[2].line, 1);  // "three" does not
  EXPECT_EQ(pieces[2].x, 0);
  // "z" and its subscript are one word: "three znpc" is 10 wide and fits the line.
  EXPECT_EQ(pieces[3].text, "z");
  EXPECT_EQ(pieces[3].line, 1);
  EXPECT_EQ(pieces[4].text, "npc");
  EXPECT_EQ(pieces[4].script, CaptionRun::Script::sub);
  EXPECT_EQ(pieces[4].x, 7);
  EXPECT_EQ(pieces[5].line, 2);
  EXPECT_EQ(lines, 3);
  // A word longer than a line gets a line of its own and is not broken.
  const auto longWord = layOutCaption("a abcdefghijklmnop b", 10, widthOf, 1, &lines);
  EXPECT_EQ(longWord[1].line, 1);
  EXPECT_EQ(longWord[1].text, "abcdefghijklmnop");
  EXPECT_EQ(longWord[2].line, 2);
  EXPECT_EQ(lines, 3);
}

}  // namespace
}  // namespace vplab
