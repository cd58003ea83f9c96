#include "app/views/caption_strip.h"

#include "app/views/caption_text.h"

#include <algorithm>
#include <cmath>

namespace vplab {

namespace {

double paddingOf(const TextMetrics& text) { return std::round(12 * text.scale()); }
TextSize sizeOf(CaptionRun::Script script) { return script == CaptionRun::Script::normal ? TextSize::title : TextSize::label; }

std::vector<CaptionPiece> layOut(std::string_view caption, int pictureWidth, const TextMetrics& text, int* lines) {
  const double width = std::max(1.0, pictureWidth - 2 * paddingOf(text));
  const CaptionMeasure widthOf = [&](std::string_view t, CaptionRun::Script script) { return double(text.measure(t, sizeOf(script)).x); };
  return layOutCaption(caption, width, widthOf, widthOf(" ", CaptionRun::Script::normal), lines);
}

}  // namespace

int captionLineCount(std::string_view caption, int pictureWidth, const TextMetrics& text) {
  int lines = 0;
  layOut(caption, pictureWidth, text, &lines);
  return lines;
}

void appendCaption(draw::Picture& picture, std::string_view heading, std::string_view caption, const TextMetrics& text,
                   Theme theme, int minLines) {
  const theme::Palette& pal = theme::palette(theme);
  const double pad = paddingOf(text);
  const double lineHeight = std::ceil(text.measure("Ag", TextSize::title).y * 1.25);
  const double headingHeight = std::ceil(text.measure("Ag", TextSize::label).y * 1.4);
  int lines = 0;
  const std::vector<CaptionPiece> pieces = layOut(caption, picture.width, text, &lines);
  lines = std::max({lines, minLines, 1});

  draw::DisplayList strip;
  strip.width = picture.width;
  strip.height = int(std::ceil(pad * 2 + headingHeight + lines * lineHeight));
  strip.background = pal.stripBackground;
  strip.observer.space = draw::Space::pixels;
  strip.antialiased = true;
  draw::Text labels{{}, pal.labelOutline};
  const glm::vec4 dim(glm::vec3(pal.text) * 0.5f + pal.stripBackground * 0.5f, 1.f);
  const Vec2 headingSize = text.measure(heading, TextSize::label);
  labels.labels.push_back({{float(pad), float(pad)}, {float(headingSize.x), float(headingSize.y)}, std::string(heading), dim, TextSize::label, false});
  const glm::vec4 accent = pal.vrp;  // the mathematics: the yellow (print: ochre) the views name VRP in
  const double titleHeight = text.measure("Ag", TextSize::title).y;
  for (const CaptionPiece& p : pieces) {
    const TextSize size = sizeOf(p.script);
    const Vec2 extent = text.measure(p.text, size);
    // Scripts sit low (sub) or high (super) against the line's title-size text.
    const double dy = p.script == CaptionRun::Script::sub ? titleHeight * 0.45 : p.script == CaptionRun::Script::super ? -titleHeight * 0.1 : 0;
    const glm::vec2 at(float(pad + p.x), float(pad + headingHeight + p.line * lineHeight + dy));
    labels.labels.push_back({at, {float(extent.x), float(extent.y)}, p.text, p.math ? accent : pal.text, size, false});
  }
  strip.add(std::move(labels));
  picture.panels.push_back({0, picture.height, std::move(strip)});
  picture.height += picture.panels.back().list.height;
}

}  // namespace vplab
