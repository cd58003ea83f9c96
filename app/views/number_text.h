// Numbers as the lecture writes them, for every place the viewer shows or copies one (matrices,
// the vertex probe, the clipping step-through, the copy buttons, SVG labels): a fixed number of
// significant digits; floating-point noise (7.96e-17 beside entries near 1) printed as 0; no "-0";
// an exponent as "7.96e-17" in text and "7.96 \times 10^{-17}" in LaTeX.
#pragma once

#include "pipeline/math.h"

#include <initializer_list>
#include <string>

namespace vplab {

struct NumberFormat {
  int digits = 4;      // significant digits (1 … 17)
  /// The magnitude of the numbers shown together with this one (a matrix's largest entry, a
  /// vector's largest component); 0: the number alone. A number smaller than half a unit of the
  /// last printed digit of `scale` is 0 up to the printing precision, and printed as 0.
  double scale = 0;
  bool latex = false;  // "7.96 \times 10^{-17}" instead of "7.96e-17"
};

std::string formatNumber(double value, const NumberFormat& format = {});

/// The largest magnitude of some numbers (for NumberFormat::scale).
double magnitudeOf(std::initializer_list<double> values);

/// "(0.1235, 0, 3.5)": the components formatted together (noise relative to the largest is 0).
std::string formatVector(const Vec3& v, int digits = 4);
std::string formatVector(const Vec4& v, int digits = 4);

}  // namespace vplab
