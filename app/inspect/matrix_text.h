// Matrices as text for the matrix panel's copy buttons: plain text, Markdown and LaTeX, in the
// column-vector form the project computes with or the lecture notes' row-vector form (the transpose).
#pragma once

#include "base/language.h"
#include "pipeline/math.h"

#include <string>
#include <string_view>

namespace vplab {

enum class MatrixFormat { plain, markdown, latex };

/// The largest magnitude among a matrix's finite entries (what its noise is measured against).
double largestEntry(const Mat4& m);

/// The LaTeX form is display math (`\[ \begin{bmatrix} … \end{bmatrix} \]`, amsmath), ready to paste.
/// The title's words are in `lang`.
std::string matrixText(const Mat4& m, std::string_view name, MatrixFormat format, bool seedForm,
                       Language lang = Language::en);

}  // namespace vplab
