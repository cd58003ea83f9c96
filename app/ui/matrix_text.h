// Matrices as text for the matrix panel's copy buttons: plain text, Markdown and LaTeX, in the
// column-vector form the project computes with or the seed's row-vector form (the transpose).
#pragma once

#include "pipeline/math.h"

#include <string>
#include <string_view>

namespace vplab {

enum class MatrixFormat { plain, markdown, latex };

std::string matrixText(const Mat4& m, std::string_view name, MatrixFormat format, bool seedForm);

}  // namespace vplab
