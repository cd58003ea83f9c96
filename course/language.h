// The languages of the course kit's sheets and feedback: English and the lecture's German.
#pragma once

#include <string_view>

namespace vplab {

enum class Language { en, de };

/// The text in the language: `en` or `de`.
inline std::string_view inLanguage(Language lang, std::string_view en, std::string_view de) {
  return lang == Language::de ? de : en;
}

}  // namespace vplab
