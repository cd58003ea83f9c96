// A lesson step's caption (app/lessons/lesson.h) as runs of text to lay out: plain words, and inline
// mathematics between $ and $ with sub- and superscripts (z_{npc}, x^{2}) and a few TeX commands
// written as their Unicode characters (\cdot ·, \times ×, \to →, \le ≤, \ge ≥, \ne ≠, \approx ≈,
// \infty ∞, \alpha α, \beta β, \phi φ, \theta θ, \lambda λ, \pi π, \sqrt √). The viewer, the SVG
// pictures and the Markdown index all draw the same runs, laid out once (layOutCaption;
// app/ui/lesson_presenter.cpp, app/views/caption_strip.h, app/commands/lesson_export.h).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

struct CaptionRun {
  enum class Script { normal, sub, super };
  std::string text;  // UTF-8
  bool math = false;
  Script script = Script::normal;
  bool operator==(const CaptionRun&) const = default;
};

/// The caption as runs, neighbours of the same kind merged. An unclosed $ is taken as a dollar sign;
/// an unknown command (\foo) is kept as written, so nothing the lecturer wrote disappears.
std::vector<CaptionRun> captionRuns(std::string_view caption);

/// A piece of a caption placed in its lines: `x` from the line's start, `line` from 0.
struct CaptionPiece {
  std::string text;
  double x = 0;
  int line = 0;
  bool math = false;
  CaptionRun::Script script = CaptionRun::Script::normal;
};
/// Measures a piece of text in its script (a backend's font: ImGui's, the views' labels).
using CaptionMeasure = std::function<double(std::string_view text, CaptionRun::Script script)>;

/// Lays the caption out in lines at most `width` wide, as every backend draws it: words never break
/// (a word wider than a line gets a line of its own), the pieces of one word (z and its subscript)
/// stay together, words are `space` apart. `lines` (if given) receives the number of lines.
std::vector<CaptionPiece> layOutCaption(std::string_view caption, double width, const CaptionMeasure& widthOf,
                                        double space, int* lines = nullptr);

/// The caption as plain text (sub- and superscripts written _x and ^x): for tooltips and alt text.
std::string captionPlainText(std::string_view caption);

/// The caption as HTML-in-Markdown: math in <i>, scripts in <sub> and <sup>, &, < and > escaped.
std::string captionMarkdown(std::string_view caption);

}  // namespace vplab
