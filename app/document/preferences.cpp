#include "app/document/preferences.h"

#include "app/document/atomic_file.h"
#include "app/text/catalogue.h"
#include "io/json_read.h"
#include "io/read_file.h"
#include "base/error.h"

#include <cstdlib>
#include <string_view>

namespace vplab {

namespace {

constexpr std::uintmax_t kMaxPreferencesBytes = 64 * 1024;  // a few keys; anything larger is not ours

std::string_view env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string_view(v) : std::string_view();
}

}  // namespace

std::filesystem::path defaultPreferencesFile() {
  if (const std::string_view config = env("XDG_CONFIG_HOME"); !config.empty() && config.front() == '/')
    return std::filesystem::path(config) / "vplab/preferences.json";
  if (const std::string_view home = env("HOME"); !home.empty()) return std::filesystem::path(home) / ".config/vplab/preferences.json";
  return {};
}

Preferences readPreferences(const std::filesystem::path& file, std::string* problem) {
  Preferences prefs;
  std::error_code ec;
  if (file.empty() || !std::filesystem::exists(file, ec)) return prefs;
  try {
    const std::string bytes = readRegularFile(file, kMaxPreferencesBytes, "preferences file");
    const JsonReader r{file.string()};
    const nlohmann::ordered_json j = parseCheckedJson(bytes, r.source, 8);
    if (!j.is_object()) r.fail("", "a JSON object expected");
    if (j.contains("language")) {
      const std::string code = r.string(j.at("language"), "/language");
      Language lang{};
      if (!text::parseLanguage(code, lang)) r.fail("/language", "\"" + code + "\": en or de expected");
      prefs.language = lang;
    }
  } catch (const Error& e) {
    if (problem) *problem = std::string(e.what()) + " (the preferences are ignored)";
    return {};
  }
  return prefs;
}

void writePreferences(const std::filesystem::path& file, const Preferences& prefs) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (prefs.language) j["language"] = std::string(text::languageCode(*prefs.language));
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  if (ec) throw Error(file.parent_path().string() + ": cannot create the preferences' directory: " + ec.message());
  writeFileAtomically(file, j.dump(2) + "\n");
}

Language languageOfEnvironment() {
  std::string_view locale;
  for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"})
    if (!(locale = env(name)).empty()) break;
  const bool plain = locale.empty() || locale == "C" || locale == "POSIX" || locale.substr(0, 2) == "C.";
  if (const std::string_view language = env("LANGUAGE"); !language.empty() && !plain) return text::languageOfLocale(language);
  return text::languageOfLocale(locale);
}

Language startLanguage(std::optional<Language> given, const Preferences& remembered) {
  if (given) return *given;
  if (remembered.language) return *remembered.language;
  return languageOfEnvironment();
}

}  // namespace vplab
