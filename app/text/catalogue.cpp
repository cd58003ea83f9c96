#include "app/text/catalogue.h"

#include <algorithm>
#include <vector>

namespace vplab::text {

namespace {

/// The number n of a placeholder "{n}" starting at text[i], or 0.
int placeholderAt(std::string_view text, std::size_t i, std::size_t& end) {
  if (text[i] != '{') return 0;
  std::size_t j = i + 1;
  int n = 0;
  while (j < text.size() && text[j] >= '0' && text[j] <= '9' && n < 100) n = n * 10 + (text[j++] - '0');
  if (j == i + 1 || j >= text.size() || text[j] != '}') return 0;
  end = j + 1;
  return n;
}

}  // namespace

std::string fill(std::string_view text, std::initializer_list<std::string_view> values) {
  std::string out;
  out.reserve(text.size() + 16 * values.size());
  for (std::size_t i = 0; i < text.size();) {
    if (text.substr(i, 2) == "{{") {
      out += '{';
      i += 2;
      continue;
    }
    std::size_t end = 0;
    const int n = placeholderAt(text, i, end);
    if (n >= 1 && std::size_t(n) <= values.size()) {
      out += *(values.begin() + (n - 1));
      i = end;
    } else {
      out += text[i++];
    }
  }
  return out;
}

std::string placeholders(std::string_view text) {
  std::vector<int> found;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.substr(i, 2) == "{{") {
      ++i;
      continue;
    }
    std::size_t end = 0;
    if (const int n = placeholderAt(text, i, end)) found.push_back(n);
  }
  std::sort(found.begin(), found.end());
  std::string out;
  for (int n : found) out += "{" + std::to_string(n) + "}";
  return out;
}

bool parseLanguage(std::string_view code, Language& out) {
  if (code == "en") out = Language::en;
  else if (code == "de") out = Language::de;
  else return false;
  return true;
}

std::string_view languageCode(Language lang) { return lang == Language::de ? "de" : "en"; }

Language languageOfLocale(std::string_view value) {
  const std::string_view first = value.substr(0, value.find(':'));
  return first.substr(0, 2) == "de" && (first.size() == 2 || first[2] == '_' || first[2] == '.' || first[2] == '@')
             ? Language::de
             : Language::en;
}

}  // namespace vplab::text
