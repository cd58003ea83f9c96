#include "app/views/caption_text.h"

#include <array>
#include <utility>

namespace vplab {

namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 15> kCommands = {{
    {"cdot", "·"}, {"times", "×"}, {"to", "→"}, {"le", "≤"}, {"ge", "≥"}, {"ne", "≠"}, {"approx", "≈"},
    {"infty", "∞"}, {"alpha", "α"}, {"beta", "β"}, {"phi", "φ"}, {"theta", "θ"}, {"lambda", "λ"},
    {"pi", "π"}, {"sqrt", "√"},
}};

bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

void append(std::vector<CaptionRun>& runs, std::string_view text, bool math, CaptionRun::Script script) {
  if (text.empty()) return;
  if (!runs.empty() && runs.back().math == math && runs.back().script == script) runs.back().text += text;
  else runs.push_back({std::string(text), math, script});
}

/// The mathematics between two $: commands replaced, _ and ^ taking a {group} or one character.
void appendMath(std::vector<CaptionRun>& runs, std::string_view m) {
  size_t i = 0;
  auto command = [&](CaptionRun::Script script) {
    size_t end = i + 1;
    while (end < m.size() && isLetter(m[end])) ++end;
    const std::string_view name = m.substr(i + 1, end - i - 1);
    for (const auto& [tex, unicode] : kCommands)
      if (name == tex) {
        append(runs, unicode, true, script);
        i = end;
        return;
      }
    append(runs, m.substr(i, std::max<size_t>(1, end - i)), true, script);  // unknown: as written
    i = std::max(end, i + 1);
  };
  while (i < m.size()) {
    const char c = m[i];
    if (c == '\\') {
      command(CaptionRun::Script::normal);
    } else if ((c == '_' || c == '^') && i + 1 < m.size()) {
      const auto script = c == '_' ? CaptionRun::Script::sub : CaptionRun::Script::super;
      ++i;
      if (m[i] == '{') {
        const size_t close = m.find('}', i);
        const size_t end = close == std::string_view::npos ? m.size() : close;
        std::vector<CaptionRun> inner;
        appendMath(inner, m.substr(i + 1, end - i - 1));
        for (const CaptionRun& r : inner) append(runs, r.text, true, script);
        i = close == std::string_view::npos ? m.size() : close + 1;
      } else if (m[i] == '\\') {
        command(script);
      } else {
        // One character, whole (a UTF-8 sequence's continuation bytes are 10xxxxxx).
        size_t end = i + 1;
        while (end < m.size() && (static_cast<unsigned char>(m[end]) & 0xC0) == 0x80) ++end;
        append(runs, m.substr(i, end - i), true, script);
        i = end;
      }
    } else {
      append(runs, m.substr(i, 1), true, CaptionRun::Script::normal);
      ++i;
    }
  }
}

std::string escapeHtml(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

}  // namespace

std::vector<CaptionRun> captionRuns(std::string_view caption) {
  std::vector<CaptionRun> runs;
  size_t i = 0;
  while (i < caption.size()) {
    const size_t open = caption.find('$', i);
    const size_t close = open == std::string_view::npos ? open : caption.find('$', open + 1);
    if (close == std::string_view::npos) {
      append(runs, caption.substr(i), false, CaptionRun::Script::normal);
      break;
    }
    append(runs, caption.substr(i, open - i), false, CaptionRun::Script::normal);
    appendMath(runs, caption.substr(open + 1, close - open - 1));
    i = close + 1;
  }
  return runs;
}

std::vector<CaptionPiece> layOutCaption(std::string_view caption, double width, const CaptionMeasure& widthOf,
                                        double space, int* lines) {
  // The words: pieces between spaces, across runs (a subscript belongs to the word before it).
  std::vector<std::vector<CaptionPiece>> words(1);
  for (const CaptionRun& r : captionRuns(caption)) {
    size_t i = 0;
    for (;;) {
      const size_t gap = r.text.find(' ', i);
      const size_t end = gap == std::string::npos ? r.text.size() : gap;
      if (end > i) words.back().push_back({r.text.substr(i, end - i), 0, 0, r.math, r.script});
      if (gap == std::string::npos) break;
      if (!words.back().empty()) words.emplace_back();
      i = gap + 1;
    }
  }
  std::vector<CaptionPiece> placed;
  double x = 0;
  int line = 0;
  for (std::vector<CaptionPiece>& word : words) {
    if (word.empty()) continue;
    double w = 0;
    for (const CaptionPiece& p : word) w += widthOf(p.text, p.script);
    if (x > 0 && x + space + w > width) {
      x = 0;
      ++line;
    } else if (x > 0) {
      x += space;
    }
    for (CaptionPiece& p : word) {
      p.x = x;
      p.line = line;
      x += widthOf(p.text, p.script);
      placed.push_back(std::move(p));
    }
  }
  if (lines) *lines = placed.empty() ? 0 : line + 1;
  return placed;
}

std::string captionPlainText(std::string_view caption) {
  std::string out;
  for (const CaptionRun& r : captionRuns(caption)) {
    if (r.script == CaptionRun::Script::normal) out += r.text;
    else {
      const bool one = r.text.size() == 1;
      out += (r.script == CaptionRun::Script::sub ? "_" : "^") + (one ? r.text : "{" + r.text + "}");
    }
  }
  return out;
}

std::string captionMarkdown(std::string_view caption) {
  std::string out;
  bool inMath = false;
  for (const CaptionRun& r : captionRuns(caption)) {
    if (r.math != inMath) out += r.math ? "<i>" : "</i>";
    inMath = r.math;
    const std::string text = escapeHtml(r.text);
    if (r.script == CaptionRun::Script::sub) out += "<sub>" + text + "</sub>";
    else if (r.script == CaptionRun::Script::super) out += "<sup>" + text + "</sup>";
    else out += text;
  }
  if (inMath) out += "</i>";
  return out;
}

}  // namespace vplab
