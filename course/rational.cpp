#include "course/rational.h"

#include "base/error.h"

#include <cmath>
#include <cstdio>
#include <numeric>

namespace vplab {

namespace {

int64_t checked(__int128 v) {
  if (v > INT64_MAX || v < -INT64_MAX) throw Error("rational arithmetic overflows 64 bits");
  return int64_t(v);
}

Rational make(__int128 n, __int128 d) {
  if (d == 0) throw Error("rational division by zero");
  if (d < 0) n = -n, d = -d;
  __int128 a = n < 0 ? -n : n, b = d;
  while (b != 0) a %= b, std::swap(a, b);
  const __int128 g = a == 0 ? 1 : a;
  return Rational(checked(n / g), checked(d / g));
}

std::string decimal(double x, int places) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", places, x);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

}  // namespace

Rational::Rational(int64_t n) : num_(n), den_(1) {}

Rational::Rational(int64_t n, int64_t d) {
  if (d == 0) throw Error("rational with denominator 0");
  if (d < 0) {
    if (n == INT64_MIN || d == INT64_MIN) throw Error("rational arithmetic overflows 64 bits");
    n = -n, d = -d;
  }
  const int64_t g = std::gcd(n, d);
  num_ = n / (g == 0 ? 1 : g);
  den_ = d / (g == 0 ? 1 : g);
}

Rational Rational::operator-() const { return make(-__int128(num_), den_); }
Rational operator+(const Rational& a, const Rational& b) {
  return make(__int128(a.num_) * b.den_ + __int128(b.num_) * a.den_, __int128(a.den_) * b.den_);
}
Rational operator-(const Rational& a, const Rational& b) { return a + (-b); }
Rational operator*(const Rational& a, const Rational& b) {
  return make(__int128(a.num_) * b.num_, __int128(a.den_) * b.den_);
}
Rational operator/(const Rational& a, const Rational& b) {
  if (b.num_ == 0) throw Error("rational division by zero");
  return make(__int128(a.num_) * b.den_, __int128(a.den_) * b.num_);
}
bool operator<(const Rational& a, const Rational& b) {
  return __int128(a.num_) * b.den_ < __int128(b.num_) * a.den_;
}

std::optional<Rational> Rational::approximate(double x, int64_t maxDen, double relTol) {
  if (!std::isfinite(x) || std::abs(x) > 1e12) return std::nullopt;
  const double tol = relTol * std::max(1.0, std::abs(x));
  // Convergents h/k of the continued fraction of x; the first one close enough has the smallest
  // denominator of all fractions that close (a best approximation).
  int64_t h0 = 1, h1 = int64_t(std::floor(x)), k0 = 0, k1 = 1;
  double r = x - std::floor(x);
  for (int i = 0; i < 64; ++i) {
    if (std::abs(double(h1) / double(k1) - x) <= tol) return Rational(h1, k1);
    if (r < 1e-15) break;
    const double inv = 1.0 / r;
    const double a = std::floor(inv);
    if (a > 1e9) break;
    r = inv - a;
    const int64_t h2 = int64_t(a) * h1 + h0, k2 = int64_t(a) * k1 + k0;
    if (k2 > maxDen) break;
    h0 = h1, h1 = h2, k0 = k1, k1 = k2;
  }
  return std::nullopt;
}

std::string Rational::text() const {
  return den_ == 1 ? std::to_string(num_) : std::to_string(num_) + "/" + std::to_string(den_);
}

std::string Rational::latex() const {
  if (den_ == 1) return std::to_string(num_);
  const int64_t n = num_ < 0 ? -num_ : num_;
  return std::string(num_ < 0 ? "-" : "") + "\\frac{" + std::to_string(n) + "}{" + std::to_string(den_) + "}";
}

std::string latexNumber(double x, int places) {
  if (const auto r = Rational::approximate(x)) return r->latex();
  return decimal(x, places);
}

std::string plainNumber(double x, int places) {
  if (const auto r = Rational::approximate(x)) return r->text();
  return decimal(x, places);
}

}  // namespace vplab
