// The remembered language (app/document/preferences.h): written and read back, a broken or hostile file
// ignored with a message naming it (the viewer still starts), and the language at start: --lang, the
// remembered choice, the locale.
#include "app/document/preferences.h"
#include "base/error.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <optional>
#include <string>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::TempDir;

/// Sets environment variables for one test and puts the old values back.
class Environment {
 public:
  void set(const char* name, const char* value) {
    if (!saved_.count(name)) {
      const char* old = std::getenv(name);
      saved_[name] = old ? std::optional<std::string>(old) : std::nullopt;
    }
    if (value) ::setenv(name, value, 1);
    else ::unsetenv(name);
  }
  ~Environment() {
    for (const auto& [name, value] : saved_) {
      if (value) ::setenv(name.c_str(), value->c_str(), 1);
      else ::unsetenv(name.c_str());
    }
  }

 private:
  std::map<std::string, std::optional<std::string>> saved_;
};

TEST(Preferences, TheChosenLanguageIsWrittenAndReadBack) {
  TempDir dir;
  const fs::path file = dir.path / "config/vplab/preferences.json";  // its directory is made
  for (const Language lang : {Language::de, Language::en}) {
    writePreferences(file, Preferences{lang});
    std::string problem;
    const Preferences read = readPreferences(file, &problem);
    EXPECT_EQ(read.language, lang);
    EXPECT_EQ(problem, "");
  }
  EXPECT_EQ(test::readFile(file), "{\n  \"language\": \"en\"\n}\n");
}

TEST(Preferences, AMissingFileHoldsNoneAndSaysNothing) {
  TempDir dir;
  std::string problem;
  EXPECT_FALSE(readPreferences(dir.path / "none.json", &problem).language);
  EXPECT_EQ(problem, "");
  EXPECT_FALSE(readPreferences({}, &problem).language);
  EXPECT_EQ(problem, "");
}

TEST(Preferences, ABrokenOrHostileFileIsIgnoredNamingTheFile) {
  TempDir dir;
  const std::string deep = std::string(10000, '[') + std::string(10000, ']');
  const std::map<std::string, std::string> files = {
      {"syntax.json", "{\"language\": "},
      {"array.json", "[\"de\"]"},
      {"number.json", "{\"language\": 1}"},
      {"french.json", "{\"language\": \"fr\"}"},
      {"twice.json", "{\"language\": \"de\", \"language\": \"en\"}"},
      {"deep.json", deep},
      {"huge.json", "{\"x\": \"" + std::string(100 * 1024, 'a') + "\"}"},
  };
  for (const auto& [name, text] : files) {
    SCOPED_TRACE(name);
    const fs::path file = dir.write(name, text);
    std::string problem;
    EXPECT_FALSE(readPreferences(file, &problem).language);
    EXPECT_THAT(problem, HasSubstr(file.string()));
    EXPECT_THAT(problem, HasSubstr("ignored"));
  }
  for (const fs::path& special : {fs::path("/dev/zero"), dir.path}) {
    std::string problem;
    EXPECT_FALSE(readPreferences(special, &problem).language) << special;
    EXPECT_THAT(problem, HasSubstr(special.string()));
  }
  // A newer vplab's key is no error.
  std::string problem;
  EXPECT_EQ(readPreferences(dir.write("newer.json", "{\"language\": \"de\", \"theme\": \"light\"}"), &problem).language,
            Language::de);
  EXPECT_EQ(problem, "");
}

TEST(Preferences, AFileThatCannotBeWrittenIsAnErrorNamingIt) {
  TempDir dir;
  // Its directory would be under a regular file: no one, root included, can make it.
  const fs::path blocker = dir.write("config", "a file, not a directory");
  try {
    writePreferences(blocker / "vplab/preferences.json", Preferences{Language::de});
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr((blocker / "vplab").string()));
  }
  EXPECT_EQ(test::readFile(blocker), "a file, not a directory");
}

TEST(Preferences, TheFileIsInTheXdgConfigDirectory) {
  Environment env;
  env.set("XDG_CONFIG_HOME", "/tmp/xdg-config");
  EXPECT_EQ(defaultPreferencesFile(), fs::path("/tmp/xdg-config/vplab/preferences.json"));
  env.set("XDG_CONFIG_HOME", "relative");  // not absolute: ignored, as the XDG spec says
  env.set("HOME", "/home/student");
  EXPECT_EQ(defaultPreferencesFile(), fs::path("/home/student/.config/vplab/preferences.json"));
  env.set("XDG_CONFIG_HOME", nullptr);
  env.set("HOME", nullptr);
  EXPECT_EQ(defaultPreferencesFile(), fs::path());
}

TEST(Preferences, TheLanguageAtStartIsTheFlagThenTheChoiceThenTheLocale) {
  Environment env;
  env.set("LANGUAGE", nullptr);
  env.set("LC_ALL", nullptr);
  env.set("LC_MESSAGES", nullptr);
  env.set("LANG", "de_DE.UTF-8");
  EXPECT_EQ(languageOfEnvironment(), Language::de);
  EXPECT_EQ(startLanguage(std::nullopt, Preferences{}), Language::de);
  EXPECT_EQ(startLanguage(std::nullopt, Preferences{Language::en}), Language::en);
  EXPECT_EQ(startLanguage(Language::de, Preferences{Language::en}), Language::de);
  EXPECT_EQ(startLanguage(Language::en, Preferences{Language::de}), Language::en);
  // As gettext: LC_ALL before LC_MESSAGES before LANG; LANGUAGE first unless the locale is C.
  env.set("LC_MESSAGES", "en_GB.UTF-8");
  EXPECT_EQ(languageOfEnvironment(), Language::en);
  env.set("LANGUAGE", "de:en");
  EXPECT_EQ(languageOfEnvironment(), Language::de);
  env.set("LC_ALL", "C.UTF-8");
  EXPECT_EQ(languageOfEnvironment(), Language::en);
  env.set("LC_ALL", nullptr);
  env.set("LC_MESSAGES", nullptr);
  env.set("LANGUAGE", nullptr);
  env.set("LANG", nullptr);
  EXPECT_EQ(languageOfEnvironment(), Language::en);
}

}  // namespace
}  // namespace vplab
