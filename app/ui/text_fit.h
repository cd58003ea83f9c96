// Whether the UI's text fits its windows (docs/lecturers.md "The viewer": nothing is cut off at any UI scale,
// on a projector, a laptop or a phone).
#pragma once

#include <string>
#include <vector>

namespace vplab::ui {

/// Glyphs of the UI font drawn across the clip rectangle of their window, column or child (text cut
/// off at the side; a glyph's own overhang beyond its pen position, as of "j" or "T", excepted), and
/// ellipses ImGui put in for a shortened tab or header, in the current ImGui context's last frame:
/// "window: text cut off at (x, y), glyph U+0057". The rule every layout is held to (the
/// desktop's at every UI scale, the page's on a phone): the tests and the page's
/// window.vplab.textCutOff() call it.
std::vector<std::string> textCutOff();

}  // namespace vplab::ui
