// The catalogue (app/text/catalogue.h): every entry in both languages, with the same placeholders and
// ImGui ids, and no English name given twice (the second would never be found).
#include "app/text/catalogue.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace vplab::text {
namespace {

/// The "##id" / "###id" suffix ImGui keys a widget by: it must not change with the language.
std::string_view imguiId(std::string_view s) {
  const size_t at = s.find("##");
  return at == std::string_view::npos ? std::string_view() : s.substr(at);
}

/// printf conversions ("%d", "%.3f", "%%"), in order: ImGui formats some entries.
std::string conversions(std::string_view s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') continue;
    size_t j = i + 1;
    while (j < s.size() && std::string_view("-+ #0123456789.lhzt").find(s[j]) != std::string_view::npos) ++j;
    if (j < s.size()) out += std::string(s.substr(i, j - i + 1)) + " ";
    i = j;
  }
  return out;
}

TEST(Catalogue, EveryEntryIsInBothLanguages) {
  std::string missing;
  int n = 0;
  for (const Entry& e : kCatalogue) {
    if (e.en.empty()) missing += "\n  an entry without English (German \"" + std::string(e.de) + "\")";
    if (e.de.empty()) missing += "\n  \"" + std::string(e.en) + "\" has no German";
    ++n;
  }
  EXPECT_TRUE(missing.empty()) << "missing from app/text/*.inc:" << missing;
  EXPECT_GT(n, 100) << "the catalogue is nearly empty";
}

TEST(Catalogue, BothLanguagesHoldTheSamePlaceholdersIdsAndConversions) {
  for (const Entry& e : kCatalogue) {
    SCOPED_TRACE(std::string(e.en));
    EXPECT_EQ(placeholders(e.en), placeholders(e.de)) << "the German: \"" << e.de << "\"";
    EXPECT_EQ(imguiId(e.en), imguiId(e.de)) << "the German: \"" << e.de << "\"";
    EXPECT_EQ(conversions(e.en), conversions(e.de)) << "the German: \"" << e.de << "\"";
  }
}

TEST(Catalogue, NoNameIsGivenTwice) {
  std::map<std::string_view, int> seen;
  for (const Entry& e : kCatalogue) ++seen[e.en];
  std::string twice;
  for (const auto& [en, count] : seen)
    if (count > 1) twice += "\n  \"" + std::string(en) + "\" × " + std::to_string(count);
  EXPECT_TRUE(twice.empty()) << "given twice in app/text/*.inc (only the first is found):" << twice;
}

TEST(Catalogue, TextsAreFoundByTheirEnglishWhileCompiling) {
  constexpr Text undo = "Undo";
  EXPECT_STREQ(undo.in(Language::en), "Undo");
  EXPECT_STREQ(undo.in(Language::de), "Rückgängig");
  EXPECT_EQ(undo.english(), "Undo");
  // The key names of a German keyboard.
  EXPECT_STREQ(Text("Ctrl+Shift+S").in(Language::de), "Strg+Umschalt+S");
}

TEST(Catalogue, FillPutsTheValuesWhereEachLanguageWantsThem) {
  EXPECT_EQ(fill("{2} of {1}", {"a", "b"}), "b of a");
  EXPECT_EQ(fill("{1}, {1} and {{1}", {"x"}), "x, x and {1}");
  EXPECT_EQ(fill("{3} stays, {} and {x} too", {"a"}), "{3} stays, {} and {x} too");
  EXPECT_EQ(fill(Language::de, "exported {1}", {"/tmp/a.png"}), "exportiert: /tmp/a.png");
  EXPECT_EQ(placeholders("{2} of {1} {{3}"), "{1}{2}");
}

TEST(Catalogue, LanguagesAreReadAsTheirCodesAndLocales) {
  Language lang = Language::en;
  EXPECT_TRUE(parseLanguage("de", lang));
  EXPECT_EQ(lang, Language::de);
  EXPECT_TRUE(parseLanguage("en", lang));
  EXPECT_EQ(lang, Language::en);
  EXPECT_FALSE(parseLanguage("DE", lang));
  EXPECT_FALSE(parseLanguage("fr", lang));
  EXPECT_FALSE(parseLanguage("", lang));
  for (const char* german : {"de", "de_DE.UTF-8", "de_AT", "de.UTF-8", "de:en", "de_CH@euro"})
    EXPECT_EQ(languageOfLocale(german), Language::de) << german;
  for (const char* english : {"", "C", "C.UTF-8", "POSIX", "en_GB.UTF-8", "en:de", "dee", "fr_FR", "nl_BE"})
    EXPECT_EQ(languageOfLocale(english), Language::en) << english;
}

}  // namespace
}  // namespace vplab::text
