// The bundled lessons (assets/lessons/): each in German and English, the two showing the same
// states step by step, each step citing a section docs/sources.md lists.
#include "app/lessons/lesson.h"
#include "app/text/catalogue.h"

#include "tests/support/files.h"

#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <regex>
#include <set>
#include <string>

namespace vplab {
namespace {

LessonContext context() {
  LessonContext c;
  c.scenesDirectory = std::filesystem::path(VPLAB_ASSETS) / "scenes";
  return c;
}

/// The lab state a step shows, without the meshes' identity (each lesson loads its scenes anew).
void expectSameState(const LessonState& a, const LessonState& b) {
  EXPECT_EQ(a.scene.camera, b.scene.camera);
  EXPECT_EQ(a.scene.title, b.scene.title);
  EXPECT_EQ(a.scene.clipPlanes, b.scene.clipPlanes);
  ASSERT_EQ(a.scene.objects.size(), b.scene.objects.size());
  for (size_t i = 0; i < a.scene.objects.size(); ++i) {
    EXPECT_EQ(a.scene.objects[i].visible, b.scene.objects[i].visible) << "object " << i;
    EXPECT_EQ(a.scene.objects[i].transform, b.scene.objects[i].transform) << "object " << i;
  }
  EXPECT_EQ(a.display, b.display);
  EXPECT_EQ(a.strategy, b.strategy);
  EXPECT_EQ(a.boundingBoxTest, b.boundingBoxTest);
  EXPECT_EQ(a.morphShown, b.morphShown);
  EXPECT_EQ(a.selected, b.selected);
  EXPECT_EQ(a.tab, b.tab);
  EXPECT_EQ(a.probe, b.probe);
  EXPECT_EQ(a.stepThrough, b.stepThrough);
  EXPECT_EQ(a.highlights, b.highlights);
}

/// Whether docs/sources.md (through which the code cites the texts) lists `section`: a section of
/// the lecture notes ("15.2.2", listed as "lecture notes 15.2.2" or in a list "15.3, 15.3.1"), or
/// another text by its short name ("Hill 7.4", "DGL wiki").
bool citedInSources(const std::string& section, const std::string& sources) {
  if (section.empty() || !std::isdigit(static_cast<unsigned char>(section[0])))
    return !section.empty() && sources.find(section) != std::string::npos;
  for (size_t at = sources.find(section); at != std::string::npos; at = sources.find(section, at + 1)) {
    const char after = at + section.size() < sources.size() ? sources[at + section.size()] : ' ';
    const bool whole = !std::isdigit(static_cast<unsigned char>(after)) && !(after == '.' && at + section.size() + 1 < sources.size() &&
                                                                              std::isdigit(static_cast<unsigned char>(sources[at + section.size() + 1])));
    if (whole && at > 0 && (sources[at - 1] == ' ' || sources[at - 1] == ',')) return true;
  }
  return false;
}

TEST(BundledLessons, EachReadsInGermanAndEnglishWithTheSameStatesEachStepCitingItsSource) {
  const std::filesystem::path dir = std::filesystem::path(VPLAB_ASSETS) / "lessons";
  const std::string sources = test::readFile(std::filesystem::path(VPLAB_ASSETS) / ".." / "docs" / "sources.md");
  ASSERT_FALSE(sources.empty());
  std::map<std::string, std::map<std::string, std::filesystem::path>> byName;  // name → language → file
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string file = e.path().filename().string();
    const size_t dot = file.find('.');
    ASSERT_NE(dot, std::string::npos) << file;
    const std::string language = file.substr(dot + 1, file.size() - dot - 1 - std::string(".json").size());
    EXPECT_TRUE(language == "de" || language == "en") << file << " is not NAME.de.json or NAME.en.json";
    byName[file.substr(0, dot)][language] = e.path();
  }
  EXPECT_GE(byName.size(), 7u) << "the lecture's seven lessons";
  for (const auto& [name, files] : byName) {
    SCOPED_TRACE(name);
    ASSERT_EQ(files.size(), 2u) << "in German and English";
    const Lesson de = loadLesson(files.at("de"), context());
    const Lesson en = loadLesson(files.at("en"), context());
    EXPECT_EQ(de.language, Language::de);
    EXPECT_EQ(en.language, Language::en);
    EXPECT_NE(de.title, en.title);
    ASSERT_EQ(de.steps.size(), en.steps.size());
    EXPECT_GE(de.steps.size(), 3u);
    for (size_t i = 0; i < de.steps.size(); ++i) {
      SCOPED_TRACE("step " + std::to_string(i));
      EXPECT_EQ(de.steps[i].section, en.steps[i].section);
      EXPECT_EQ(de.steps[i].free, en.steps[i].free);
      EXPECT_NE(de.steps[i].caption, en.steps[i].caption);
      EXPECT_TRUE(citedInSources(de.steps[i].section, sources))
          << "section \"" << de.steps[i].section << "\" is not in docs/sources.md";
      expectSameState(de.steps[i].state, en.steps[i].state);
    }
  }
}

TEST(BundledLessons, AreListedByLanguage) {
  const auto de = listBundledLessons(Language::de), en = listBundledLessons(Language::en);
  ASSERT_EQ(de.size(), en.size());
  ASSERT_FALSE(de.empty());
  for (size_t i = 0; i < de.size(); ++i) {
    EXPECT_EQ(de[i].file.filename().string().substr(0, de[i].file.filename().string().find('.')),
              en[i].file.filename().string().substr(0, en[i].file.filename().string().find('.')));
    EXPECT_NE(de[i].title, en[i].title);
  }
}

// A caption that names a tab ("im Reiter Kamera", "the Clipping tab") names it as the viewer shows
// it in the caption's language (issue 37 item 5: "Reiter Camera" in the German lesson 02, whose tab
// is "Kamera").
TEST(BundledLessons, ACaptionNamesATabAsTheViewerDoesInItsLanguage) {
  size_t named = 0;
  for (const Language language : {Language::en, Language::de}) {
    std::set<std::string> tabs;
    for (const text::Text t : {text::Text("Camera"), text::Text("Scene"), text::Text("Clipping"), text::Text("Display"),
                               text::Text("Lecture"), text::Text("Vertex probe"), text::Text("Matrices"), text::Text("Depth")})
      tabs.insert(t.in(language));
    // German: "Reiter X"; English: "X tab" (a one- or two-word name).
    const std::regex tabRef = language == Language::de ? std::regex("Reiter ([A-ZÄÖÜ][^ ,.;:()]*)")
                                                       : std::regex("([A-Z][a-z]+(?: probe)?) tab\\b");
    for (const LessonFileInfo& info : listBundledLessons(language)) {
      const Lesson lesson = loadLesson(info.file, context());
      for (size_t i = 0; i < lesson.steps.size(); ++i) {
        const std::string& caption = lesson.steps[i].caption;
        for (std::sregex_iterator m(caption.begin(), caption.end(), tabRef), end; m != end; ++m) {
          ++named;
          EXPECT_TRUE(tabs.count((*m)[1].str()))
              << info.file.filename().string() << " step " << i + 1 << " names the tab \"" << (*m)[1].str()
              << "\", which the viewer does not show in this language";
        }
      }
    }
  }
  EXPECT_GT(named, 10u) << "the lessons name tabs in both languages";
}

}  // namespace
}  // namespace vplab
