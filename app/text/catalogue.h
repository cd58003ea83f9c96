// The catalogue: every text vplab shows a user (menus, panels, the views' labels, messages, help, the
// page), in English and in the lecture's German, in one place (docs/lecturers.md "German and English").
//
// A text is named by its English, as gettext names it by its msgid, so the code reads as the window
// does: ui::tr(s, "Undo"). The name is looked up while compiling (Text's constructor is consteval):
// a text that is not in the catalogue does not compile, and no text is looked up at run time. What a
// text holds besides words is {1}, {2}, … (fill() puts the values in, in the order the language
// needs them) and ImGui's "##id" / "###id" suffixes, which the catalogue's entries carry unchanged.
// tests/app/text/catalogue_test.cpp fails on an entry missing in either language, on differing
// placeholders and on a name given twice.
//
// The entries are the files beside this one, one per part of the program (what a translator edits):
//   ui_menus.inc                     the menu bar, help (F1), View ▸ Language
//   ui_panels_camera_scene.inc       the controls' Camera and Scene tabs
//   ui_panels_clipping_inspect.inc   the Clipping and Display tabs, the inspector
//   ui_lecture_views.inc             the Lecture tab, the lessons' box, the views' windows
//   ui_messages.inc                  the viewer's frame and the session: files, dialogs, the status line
//   views.inc                        the labels and titles the views draw (also in exported pictures)
//   camera.inc                       what makes a camera invalid (app/inspect/camera_text.cpp)
//   page.inc                         the page's own texts (app/web/)
//   practice.inc                     an exercise practised: the Tasks panel, Check, Hand in
//   links.inc                        a link's parts not understood (app/document/url_state.cpp)
#pragma once

#include "base/language.h"

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

namespace vplab::text {

/// One text in both languages. `de` empty: not translated yet (the catalogue's test fails).
struct Entry {
  std::string_view en;
  std::string_view de;
};

// clang-format off
inline constexpr Entry kCatalogue[] = {
#include "app/text/ui_menus.inc"
#include "app/text/ui_panels_camera_scene.inc"
#include "app/text/ui_panels_clipping_inspect.inc"
#include "app/text/ui_lecture_views.inc"
#include "app/text/ui_messages.inc"
#include "app/text/views.inc"
#include "app/text/camera.inc"
#include "app/text/page.inc"
#include "app/text/practice.inc"
#include "app/text/links.inc"
};
// clang-format on

/// The entry named `en`. Evaluated while compiling only: a name missing from the catalogue is an
/// error at the call ("… is not a constant expression" at the throw below).
consteval std::size_t indexOf(std::string_view en) {
  for (std::size_t i = 0; i < std::size(kCatalogue); ++i)
    if (kCatalogue[i].en == en) return i;
  throw "a text missing from the catalogue (app/text/*.inc)";
}

/// A text of the catalogue, named by its English: `Text t = "Undo";` compiles only when the catalogue
/// holds "Undo".
class Text {
 public:
  consteval Text(const char* en) : index_(indexOf(en)) {}  // NOLINT: implicit, as a string literal reads
  /// The text in `lang`, NUL-terminated; the English when the German is missing.
  const char* in(Language lang) const {
    const Entry& e = kCatalogue[index_];
    return (lang == Language::de && !e.de.empty() ? e.de : e.en).data();
  }
  std::string_view english() const { return kCatalogue[index_].en; }

 private:
  std::size_t index_;
};

/// `text` with {1}, {2}, … replaced by `values` in that order ({{ is a brace); a placeholder without
/// a value stays as written.
std::string fill(std::string_view text, std::initializer_list<std::string_view> values);
inline std::string fill(Language lang, Text text, std::initializer_list<std::string_view> values) {
  return fill(text.in(lang), values);
}

/// The placeholders of a text in order of their number ("{1}{2}"), for the catalogue's test.
std::string placeholders(std::string_view text);

/// "de" or "en" → the language; anything else → nothing (the caller names what it read).
bool parseLanguage(std::string_view code, Language& out);
std::string_view languageCode(Language lang);
/// The language of a POSIX locale's value ($LANGUAGE's first entry, $LC_ALL, $LC_MESSAGES, $LANG:
/// "de_DE.UTF-8", "de:en"): German for "de…", English for anything else.
Language languageOfLocale(std::string_view value);

}  // namespace vplab::text
