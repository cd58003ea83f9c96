// The names of the views, styles and themes (the command line's --view, --style and --theme, the scene files).
#include "app/views/views.h"

namespace vplab {

std::string_view toString(ViewKind v) {
  switch (v) {
    case ViewKind::camera: return "camera";
    case ViewKind::world: return "world";
    case ViewKind::npc: return "npc";
    case ViewKind::all: return "all";
    case ViewKind::morph: return "morph";
    case ViewKind::divideFirst: return "divide-first";
    case ViewKind::depth: return "depth-plot";
  }
  return "?";
}

std::optional<ViewKind> viewKindFromString(std::string_view s) {
  for (ViewKind v : kAllViewKinds)
    if (toString(v) == s) return v;
  return std::nullopt;
}

std::string_view toString(Style s) {
  switch (s) {
    case Style::flat: return "flat";
    case Style::shaded: return "shaded";
    case Style::wire: return "wire";
    case Style::hiddenLine: return "hidden-line";
    case Style::hiddenRemoved: return "hidden-removed";
  }
  return "?";
}

std::optional<Style> styleFromString(std::string_view s) {
  for (Style st : kAllStyles)
    if (toString(st) == s) return st;
  return std::nullopt;
}

std::string_view toString(Theme t) { return t == Theme::light ? "light" : "dark"; }

std::optional<Theme> themeFromString(std::string_view s) {
  for (Theme t : {Theme::dark, Theme::light})
    if (toString(t) == s) return t;
  return std::nullopt;
}

}  // namespace vplab
