// The bundled lessons, for the tests that walk every step of each (lesson_layout_test.cpp at the
// projector's sizes, lesson_phone_test.cpp on a phone).
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace vplab::test {

/// The file names of assets/lessons/*.json, sorted ("05-clipping.de.json").
inline std::vector<std::string> bundledLessons() {
  std::vector<std::string> names;
  for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(std::filesystem::path(VPLAB_ASSETS) / "lessons"))
    if (e.path().extension() == ".json") names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// A lesson's file name as a test's name: "05-clipping.de.json" → "05_clipping_de".
inline std::string lessonTestName(std::string file) {
  file = file.substr(0, file.size() - 5);
  for (char& c : file)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return file;
}

}  // namespace vplab::test
