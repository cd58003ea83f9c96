// A caption under a picture: a lesson's step as a still or an animation's frame (app/lessons/)
// carries its heading and caption below the views, so that a slide or a course page needs no text
// of its own. Laid out once here (layOutCaption, app/views/caption_text.h) for every backend.
#pragma once

#include "app/views/display_list.h"
#include "app/views/labels.h"
#include "app/views/theme.h"

#include <string_view>

namespace vplab {

/// Adds a strip as wide as `picture` under it: `heading` on the first line (the lesson, the step and
/// its section, dim), then `caption` in lines of the title size, its mathematics in the accent colour
/// and its sub- and superscripts at the label size, in at least `minLines` lines' height (the pictures
/// of one lesson are all as tall as its longest caption needs). The picture grows by the strip's height.
void appendCaption(draw::Picture& picture, std::string_view heading, std::string_view caption, const TextMetrics& text,
                   Theme theme, int minLines = 1);

/// The lines `caption` takes under a picture `pictureWidth` pixels wide.
int captionLineCount(std::string_view caption, int pictureWidth, const TextMetrics& text);

}  // namespace vplab
