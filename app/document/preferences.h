// The user's preferences that outlive a session (docs/lecturers.md "German and English"): the language chosen
// in View ▸ Language. A small JSON file in the XDG configuration directory
// ($XDG_CONFIG_HOME/vplab/preferences.json, by default ~/.config/vplab/preferences.json), written
// atomically; the page keeps the same in localStorage (app/web/page.cpp).
//
// The language at start: --lang, else the remembered choice, else the locale ($LANGUAGE, $LC_ALL,
// $LC_MESSAGES, $LANG, as gettext reads them), else English.
#pragma once

#include "base/language.h"

#include <filesystem>
#include <optional>
#include <string>

namespace vplab {

struct Preferences {
  std::optional<Language> language;  // View ▸ Language, when the user chose one
};

/// $XDG_CONFIG_HOME/vplab/preferences.json, else $HOME/.config/vplab/preferences.json; empty when
/// neither variable is set (nothing is remembered).
std::filesystem::path defaultPreferencesFile();

/// The preferences in `file`. A missing file holds none. A file that cannot be read or is not a
/// preferences file (too large, not JSON, a wrong value) holds none either, and `problem` says why,
/// naming the file: a broken file must not keep the viewer from starting. Unknown keys are left
/// ignored (a newer vplab's; writing drops them).
Preferences readPreferences(const std::filesystem::path& file, std::string* problem = nullptr);

/// Writes `prefs` to `file` atomically, creating its directory. Throws vplab::Error naming the file.
void writePreferences(const std::filesystem::path& file, const Preferences& prefs);

/// The language a POSIX environment asks for: $LANGUAGE's first entry (unless the locale is C or
/// POSIX, which gettext also ignores it for), else the first set of $LC_ALL, $LC_MESSAGES, $LANG;
/// German for "de…", else English.
Language languageOfEnvironment();

/// The language at start: `given` (--lang), else the remembered one, else the environment's.
Language startLanguage(std::optional<Language> given, const Preferences& remembered);

}  // namespace vplab
