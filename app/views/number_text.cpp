#include "app/views/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace vplab {

std::string formatNumber(double value, const NumberFormat& format) {
  if (std::isnan(value)) return format.latex ? "\\mathrm{NaN}" : "NaN";
  if (std::isinf(value)) return value < 0 ? (format.latex ? "-\\infty" : "-inf") : (format.latex ? "\\infty" : "inf");
  const int digits = std::clamp(format.digits, 1, 17);
  // Noise: below half a unit in the last printed digit of the numbers shown with it.
  if (format.scale > 0) {
    const double unit = std::pow(10.0, std::floor(std::log10(format.scale)) - (digits - 1));
    if (std::abs(value) < 0.5 * unit) value = 0;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  std::string text = buf;
  if (text == "-0") return "0";  // a negative value rounded to zero
  const size_t e = text.find('e');
  if (e == std::string::npos) return text;
  // "7.96e-17": the exponent without "+" and leading zeros.
  const std::string mantissa = text.substr(0, e);
  const int exponent = std::atoi(text.c_str() + e + 1);
  if (!format.latex) return mantissa + "e" + std::to_string(exponent);
  const std::string power = "10^{" + std::to_string(exponent) + "}";
  if (mantissa == "1") return power;
  if (mantissa == "-1") return "-" + power;
  return mantissa + " \\times " + power;
}

double magnitudeOf(std::initializer_list<double> values) {
  double m = 0;
  for (double v : values)
    if (std::isfinite(v)) m = std::max(m, std::abs(v));
  return m;
}

std::string formatVector(const Vec3& v, int digits) {
  const NumberFormat f{digits, magnitudeOf({v.x, v.y, v.z})};
  return "(" + formatNumber(v.x, f) + ", " + formatNumber(v.y, f) + ", " + formatNumber(v.z, f) + ")";
}

std::string formatVector(const Vec4& v, int digits) {
  const NumberFormat f{digits, magnitudeOf({v.x, v.y, v.z, v.w})};
  return "(" + formatNumber(v.x, f) + ", " + formatNumber(v.y, f) + ", " + formatNumber(v.z, f) + ", " +
         formatNumber(v.w, f) + ")";
}

}  // namespace vplab
