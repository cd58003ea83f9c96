#include "app/ui/matrix_text.h"

#include <cstdio>

namespace vplab {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v == 0 ? 0.0 : v);  // no "-0"
  return buf;
}

}  // namespace

std::string matrixText(const Mat4& m, std::string_view name, MatrixFormat format, bool seedForm) {
  const Mat4 shown = seedForm ? glm::transpose(m) : m;
  const std::string title = std::string(name) + (seedForm ? " (seed's row-vector form, p' = p · M)" : " (p' = M · p)");
  const auto rows = rowsOf(shown);
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
      out = "% " + title + "\n\\begin{pmatrix}\n";
      for (size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        out += "  " + number(r[0]) + " & " + number(r[1]) + " & " + number(r[2]) + " & " + number(r[3]) +
               (i + 1 < rows.size() ? " \\\\\n" : "\n");
      }
      return out + "\\end{pmatrix}\n";
  }
  return out;
}

}  // namespace vplab
