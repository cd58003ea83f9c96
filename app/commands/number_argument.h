// A number given on the command line: the whole argument, finite, within its range. Shared by the
// viewer's and render's options (cli.cpp) and the course staff's (course_commands.cpp).
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace vplab {

/// `text` read whole as a finite number in [lo, hi]; nothing for a typo, trailing text ("2cm"),
/// "nan", "inf" or a value outside the range.
inline std::optional<double> numberArgument(const std::string& text, double lo, double hi) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v) || v < lo || v > hi) return std::nullopt;
  return v;
}

}  // namespace vplab
