#include "app/inspect/matrix_text.h"

#include "app/text/catalogue.h"
#include "app/views/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vplab {

double largestEntry(const Mat4& m) {
  double largest = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (std::isfinite(m[c][r])) largest = std::max(largest, std::abs(m[c][r]));
  return largest;
}

std::string matrixText(const Mat4& m, std::string_view name, MatrixFormat format, bool seedForm, Language lang) {
  const Mat4 shown = seedForm ? glm::transpose(m) : m;
  const std::string title = seedForm ? text::fill(lang, "{1} (lecture notes' row-vector form, p' = p · M)", {name})
                                     : std::string(name) + " (p' = M · p)";
  const auto rows = rowsOf(shown);
  const NumberFormat plain{6, largestEntry(m)};
  NumberFormat latex = plain;
  latex.latex = true;
  auto number = [&](double v) { return formatNumber(v, format == MatrixFormat::latex ? latex : plain); };
  std::string out;
  switch (format) {
    case MatrixFormat::plain:
      out = title + "\n";
      for (const auto& r : rows) {
        char line[160];
        std::snprintf(line, sizeof line, "%12s %12s %12s %12s\n", number(r[0]).c_str(), number(r[1]).c_str(),
                      number(r[2]).c_str(), number(r[3]).c_str());
        out += line;
      }
      return out;
    case MatrixFormat::markdown:
      out = "**" + title + "**\n\n|   |   |   |   |\n|---|---|---|---|\n";
      for (const auto& r : rows)
        out += "| " + number(r[0]) + " | " + number(r[1]) + " | " + number(r[2]) + " | " + number(r[3]) + " |\n";
      return out;
    case MatrixFormat::latex:
      // Display math, ready to paste into a document that loads amsmath (bmatrix).
      out = "% " + text::fill(lang, "{1} (needs \\usepackage{amsmath})", {title}) + "\n\\[\n\\begin{bmatrix}\n";
      for (size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        out += "  " + number(r[0]) + " & " + number(r[1]) + " & " + number(r[2]) + " & " + number(r[3]) +
               (i + 1 < rows.size() ? " \\\\\n" : "\n");
      }
      return out + "\\end{bmatrix}\n\\]\n";
  }
  return out;
}

}  // namespace vplab
