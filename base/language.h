// The languages vplab speaks: English and the lecture's German (the course kit's sheets and feedback,
// the labels in the views). A plain value every layer may use.
#pragma once

#include <string_view>

namespace vplab {

enum class Language { en, de };

/// The text in the language: `en` or `de`.
inline std::string_view inLanguage(Language lang, std::string_view en, std::string_view de) {
  return lang == Language::de ? de : en;
}

}  // namespace vplab
