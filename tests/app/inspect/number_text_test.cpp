// formatNumber (app/views/number_text.h): the one way numbers are printed, and the matrix copies made with it.
#include "app/views/number_text.h"
#include "app/inspect/matrix_text.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace vplab {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(NumberText, NoiseBesideLargerNumbersIsZero) {
  // cos 90° beside entries of 1: noise at 4 (and 6) significant digits.
  EXPECT_EQ(formatNumber(std::cos(std::acos(-1.0) / 2), {4, 1.0}), "0");
  EXPECT_EQ(formatNumber(7.96e-17, {6, 1.0}), "0");
  EXPECT_EQ(formatNumber(-7.96e-17, {6, 1.0}), "0") << "no -0";
  // Half a unit of the last digit is the border: 0.00049 is 0 at 4 digits of 1, 0.0006 is not.
  EXPECT_EQ(formatNumber(0.00049, {4, 1.0}), "0");
  EXPECT_EQ(formatNumber(0.0006, {4, 1.0}), "0.0006");
  // Alone (no scale) a small number is a number.
  EXPECT_EQ(formatNumber(7.96e-17, {4, 0}), "7.96e-17");
  EXPECT_EQ(formatNumber(-2.5e-5, {4, 0}), "-2.5e-5");
}

TEST(NumberText, RoundNumbersAreRound) {
  EXPECT_EQ(formatNumber(0.99999999999), "1");
  EXPECT_EQ(formatNumber(2.0000000001), "2");
  EXPECT_EQ(formatNumber(-0.0), "0");
  EXPECT_EQ(formatNumber(-1e-30, {4, 5.0}), "0");
  EXPECT_EQ(formatNumber(0.1 + 0.2), "0.3");
  EXPECT_EQ(formatNumber(8.42734, {4}), "8.427");
  EXPECT_EQ(formatNumber(123456.0, {4}), "1.235e5");
}

TEST(NumberText, LatexWritesPowersOfTen) {
  EXPECT_EQ(formatNumber(7.96e-17, {3, 0, true}), "7.96 \\times 10^{-17}");
  EXPECT_EQ(formatNumber(1e-20, {4, 0, true}), "10^{-20}");
  EXPECT_EQ(formatNumber(-1e8, {4, 0, true}), "-10^{8}");
  EXPECT_EQ(formatNumber(0.5, {4, 0, true}), "0.5");
  EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity(), {4, 0, true}), "\\infty");
  EXPECT_EQ(formatNumber(std::nan(""), {4, 0}), "NaN");
}

TEST(NumberText, VectorsShareTheirScale) {
  EXPECT_EQ(formatVector(Vec3(0.9285, 1e-17, -0.3714)), "(0.9285, 0, -0.3714)");
  EXPECT_EQ(formatVector(Vec4(1e-17, 1e-17, 1e-17, 1e-17)), "(1e-17, 1e-17, 1e-17, 1e-17)") << "all tiny: real";
}

// The cube rotated by 90° about y (issue 11 item 8): its matrix has cos 90° = 6.1e-17 entries.
Mat4 rotated90() {
  const double c = std::cos(std::acos(-1.0) / 2), sn = std::sin(std::acos(-1.0) / 2);
  Mat4 m(1.0);
  m[0][0] = c;
  m[0][2] = -sn;
  m[2][0] = sn;
  m[2][2] = c;
  return m;
}

TEST(NumberText, MatrixCopiesShowNoNoise) {
  const Mat4 m = rotated90();
  ASSERT_NE(m[0][0], 0.0) << "the noise this test is about";
  for (MatrixFormat f : {MatrixFormat::plain, MatrixFormat::markdown, MatrixFormat::latex}) {
    const std::string text = matrixText(m, "wcFromMc", f, false);
    EXPECT_THAT(text, Not(HasSubstr("e-"))) << text;
    EXPECT_THAT(text, Not(HasSubstr("-0 "))) << text;
  }
}

// The LaTeX copy pastes into a document as it is: display math around an amsmath bmatrix, the
// rows separated by \\, no bare exponent notation.
TEST(NumberText, LatexCopyIsReadyToPaste) {
  Mat4 m(1.0);
  m[3][0] = 7.96e-17;  // alone in its matrix of 1s and 0s: noise, 0
  m[3][1] = 2.5e-9;    // noise too at 6 digits of 1
  const std::string text = matrixText(m, "dcFromNpc", MatrixFormat::latex, false);
  EXPECT_THAT(text, HasSubstr("\\[\n\\begin{bmatrix}\n"));
  EXPECT_THAT(text, HasSubstr("\\end{bmatrix}\n\\]\n"));
  EXPECT_THAT(text, HasSubstr("amsmath"));
  EXPECT_THAT(text, HasSubstr("  1 & 0 & 0 & 0 \\\\\n"));
  EXPECT_THAT(text, Not(HasSubstr("e-")));
  Mat4 big(1.0);
  big[0][0] = 1e-20;
  big[1][1] = 1e-20;
  big[2][2] = 1e-20;
  big[3][3] = 3e-20;
  EXPECT_THAT(matrixText(big, "tiny", MatrixFormat::latex, false), HasSubstr("3 \\times 10^{-20}"));
}

}  // namespace
}  // namespace vplab
