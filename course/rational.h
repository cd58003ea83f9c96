// Exact fractions for the worked solutions of `vplab exercise` (issue 14): the pipeline computes in
// double precision; where an exercise's inputs (small integers and halves, Pythagorean directions)
// make a value a small rational, the solution prints it as that fraction. A value is shown as a
// fraction only when a fraction with a small denominator reproduces the double to within 1e-11
// (relative: the few roundings of an exact computation stay far below it, while a decimal that is no
// such fraction hits one by chance with a probability of about 1e-5·|x|), else as a decimal with a stated number of places.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace vplab {

/// num / den in lowest terms, den > 0. Arithmetic throws vplab::Error on overflow of 64 bits and on
/// division by zero, never wraps.
class Rational {
 public:
  constexpr Rational() = default;
  Rational(int64_t n);  // NOLINT: an integer is a rational
  Rational(int64_t n, int64_t d);

  int64_t num() const { return num_; }
  int64_t den() const { return den_; }
  double toDouble() const { return double(num_) / double(den_); }

  Rational operator-() const;
  friend Rational operator+(const Rational& a, const Rational& b);
  friend Rational operator-(const Rational& a, const Rational& b);
  friend Rational operator*(const Rational& a, const Rational& b);
  friend Rational operator/(const Rational& a, const Rational& b);
  friend bool operator==(const Rational& a, const Rational& b) = default;
  friend bool operator<(const Rational& a, const Rational& b);

  /// The fraction with the smallest denominator ≤ maxDen within relTol·max(1, |x|) of x (best
  /// rational approximations by continued fractions), or nullopt when none is that close or x is
  /// not finite.
  static std::optional<Rational> approximate(double x, int64_t maxDen = 1000, double relTol = 1e-11);

  /// "3", "-3/10".
  std::string text() const;
  /// "3", "-\frac{3}{10}" (for LaTeX math).
  std::string latex() const;

 private:
  int64_t num_ = 0, den_ = 1;
};

/// A double as LaTeX math: its small fraction when Rational::approximate finds one, else a decimal
/// rounded to `places` places ("0.7071"); "-0" is written "0".
std::string latexNumber(double x, int places = 4);
/// The same in plain text ("-3/10", "0.7071").
std::string plainNumber(double x, int places = 4);

}  // namespace vplab
