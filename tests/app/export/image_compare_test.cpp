// Image comparison (app/export/image_compare.h): counts, share, max and mean deltas, the threshold, the
// worst pixels, the size mismatch report and the difference picture.
#include "app/export/image_compare.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "base/error.h"
#include "tests/support/test_util.h"

namespace vplab {
namespace {

using ::testing::HasSubstr;

const Rgba kGrey{100, 100, 100, 255};

/// A 4 × 3 image of one colour with a few pixels changed.
Image imageWith(std::initializer_list<std::pair<std::pair<int, int>, Rgba>> changes) {
  Image image(4, 3, kGrey);
  for (const auto& [xy, color] : changes) image.at(xy.first, xy.second) = color;
  return image;
}

TEST(ImageCompare, IdenticalImagesAgree) {
  const Image a = imageWith({{{1, 2}, {10, 20, 30, 255}}});
  const ImageComparison c = compareImages(a, a, 0);
  EXPECT_TRUE(c.passed());
  EXPECT_FALSE(c.sizeMismatch);
  EXPECT_EQ(c.pixelCount, 12u);
  EXPECT_EQ(c.differingPixels, 0u);
  EXPECT_EQ(c.differingShare, 0);
  EXPECT_EQ(c.maxChannelDelta, 0);
  EXPECT_EQ(c.meanChannelDelta, 0);
  EXPECT_TRUE(c.worst.empty());
}

// Two pixels differ: (1, 0) by 10 in red and 4 in blue (its delta is the larger, 10), (3, 2) by 155
// in green. Mean over 12 pixels × 4 channels: (10 + 4 + 255) / 48.
TEST(ImageCompare, KnownDeltasGiveCountsShareMaxAndMean) {
  const Image expected = imageWith({});
  const Image actual = imageWith({{{1, 0}, {110, 100, 96, 255}}, {{3, 2}, {100, 255, 100, 255}}});
  const ImageComparison c = compareImages(actual, expected, 0);
  EXPECT_FALSE(c.passed());
  EXPECT_EQ(c.differingPixels, 2u);
  EXPECT_DOUBLE_EQ(c.differingShare, 2.0 / 12);
  EXPECT_EQ(c.maxChannelDelta, 155);
  EXPECT_DOUBLE_EQ(c.meanChannelDelta, (10 + 4 + 155) / 48.0);
  ASSERT_EQ(c.worst.size(), 2u);
  EXPECT_EQ(c.worst[0].x, 3);
  EXPECT_EQ(c.worst[0].y, 2);
  EXPECT_EQ(c.worst[0].delta, 155);
  EXPECT_EQ(c.worst[0].actual, (Rgba{100, 255, 100, 255}));
  EXPECT_EQ(c.worst[0].expected, kGrey);
  EXPECT_EQ(c.worst[1].x, 1);
  EXPECT_EQ(c.worst[1].y, 0);
  EXPECT_EQ(c.worst[1].delta, 10);
}

// A pixel differs when some channel differs by MORE than the threshold.
TEST(ImageCompare, ThresholdIsExclusive) {
  const Image expected = imageWith({});
  const Image actual = imageWith({{{0, 0}, {103, 100, 100, 255}}, {{1, 0}, {100, 96, 100, 255}}});
  EXPECT_EQ(compareImages(actual, expected, 2).differingPixels, 2u);
  EXPECT_EQ(compareImages(actual, expected, 3).differingPixels, 1u);  // only the 4
  EXPECT_EQ(compareImages(actual, expected, 4).differingPixels, 0u);
  EXPECT_TRUE(compareImages(actual, expected, 4).passed());
  // Max and mean describe all pixels, whatever the threshold.
  EXPECT_EQ(compareImages(actual, expected, 4).maxChannelDelta, 4);
  EXPECT_DOUBLE_EQ(compareImages(actual, expected, 4).meanChannelDelta, 7 / 48.0);
}

TEST(ImageCompare, AlphaDifferencesCount) {
  const Image actual = imageWith({{{2, 1}, {100, 100, 100, 0}}});
  const ImageComparison c = compareImages(actual, imageWith({}), 0);
  EXPECT_EQ(c.differingPixels, 1u);
  EXPECT_EQ(c.maxChannelDelta, 255);
}

TEST(ImageCompare, WorstPixelsAreSortedByDeltaAndLimited) {
  const Image expected = imageWith({});
  const Image actual = imageWith({{{0, 0}, {101, 100, 100, 255}},
                                  {{1, 1}, {100, 150, 100, 255}},
                                  {{2, 2}, {100, 100, 120, 255}},
                                  {{3, 0}, {0, 100, 100, 255}},
                                  {{0, 2}, {100, 100, 100, 250}}});
  const ImageComparison c = compareImages(actual, expected, 0, 3);
  EXPECT_EQ(c.differingPixels, 5u);
  ASSERT_EQ(c.worst.size(), 3u);
  EXPECT_EQ(c.worst[0].delta, 100);
  EXPECT_EQ(c.worst[0].x, 3);
  EXPECT_EQ(c.worst[1].delta, 50);
  EXPECT_EQ(c.worst[2].delta, 20);
  EXPECT_TRUE(compareImages(actual, expected, 0, 0).worst.empty());
  EXPECT_EQ(compareImages(actual, expected, 0, 100).worst.size(), 5u);
}

// Equal deltas are listed in row-major order (y, then x), so the report is deterministic.
TEST(ImageCompare, EqualDeltasAreListedInRowMajorOrder) {
  const Rgba off{90, 100, 100, 255};
  const Image actual = imageWith({{{3, 2}, off}, {{0, 1}, off}, {{2, 0}, off}, {{1, 1}, off}});
  const ImageComparison c = compareImages(actual, imageWith({}), 0);
  ASSERT_EQ(c.worst.size(), 4u);
  const int order[4][2] = {{2, 0}, {0, 1}, {1, 1}, {3, 2}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(c.worst[i].x, order[i][0]) << i;
    EXPECT_EQ(c.worst[i].y, order[i][1]) << i;
  }
}

// Row by row (`vplab grade image`'s strips): the rows given in any order give what the whole
// images give, the worst pixels with their colours and places included.
TEST(ImageCompare, RowsInAnyOrderGiveTheWholeComparison) {
  const Image expected = imageWith({{{1, 0}, {0, 0, 0, 255}}});
  const Image actual = imageWith({{{0, 0}, {101, 100, 100, 255}},
                                  {{1, 1}, {100, 150, 100, 255}},
                                  {{2, 2}, {100, 100, 120, 255}},
                                  {{3, 0}, {0, 100, 100, 255}},
                                  {{0, 2}, {100, 100, 100, 250}}});
  const ImageComparison whole = compareImages(actual, expected, 5, 3);
  RowComparer rows(4, 3, 5, 3);
  for (int y : {2, 0, 1}) rows.add(y, actual.row(y), expected.row(y));
  const ImageComparison byRows = std::move(rows).result();
  EXPECT_EQ(byRows.differingPixels, whole.differingPixels);
  EXPECT_EQ(byRows.maxChannelDelta, whole.maxChannelDelta);
  EXPECT_DOUBLE_EQ(byRows.meanChannelDelta, whole.meanChannelDelta);
  EXPECT_DOUBLE_EQ(byRows.differingShare, whole.differingShare);
  ASSERT_EQ(byRows.worst.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(byRows.worst[i].x, whole.worst[i].x) << i;
    EXPECT_EQ(byRows.worst[i].y, whole.worst[i].y) << i;
    EXPECT_EQ(byRows.worst[i].actual, whole.worst[i].actual) << i;
    EXPECT_EQ(byRows.worst[i].expected, whole.worst[i].expected) << i;
  }
  // The expected values, counted by hand: (1, 0) black against grey (delta 100), (3, 0) 100, (1, 1) 50,
  // (2, 2) 20; (0, 0) and (0, 2) within the threshold 5.
  EXPECT_EQ(whole.differingPixels, 4u);
  EXPECT_EQ(whole.worst[0].x, 1);
  EXPECT_EQ(whole.worst[1].x, 3);
  EXPECT_EQ(whole.worst[2].delta, 50);
}

TEST(ImageCompare, SizeMismatchIsReportedNotCompared) {
  const ImageComparison c = compareImages(Image(320, 240), Image(640, 480), 0);
  EXPECT_TRUE(c.sizeMismatch);
  EXPECT_FALSE(c.passed());
  EXPECT_EQ(c.actualWidth, 320);
  EXPECT_EQ(c.expectedHeight, 480);
  EXPECT_THAT(describe(c), HasSubstr("actual 320 × 240, expected 640 × 480"));
  // Same pixel count, different shape: still a mismatch.
  EXPECT_TRUE(compareImages(Image(2, 6), Image(4, 3), 0).sizeMismatch);
}

TEST(ImageCompare, DescribeNamesCountsShareDeltasAndWorstPixels) {
  const Image expected = imageWith({});
  const Image actual = imageWith({{{1, 0}, {110, 100, 96, 255}}, {{3, 2}, {100, 255, 100, 255}}});
  const std::string text = describe(compareImages(actual, expected, 5, 1));
  EXPECT_THAT(text, HasSubstr("2 of 12 pixels (16.6667 %) differ by more than 5"));
  EXPECT_THAT(text, HasSubstr("max channel delta 155"));
  EXPECT_THAT(text, HasSubstr("mean channel delta 3.5208"));  // 169 / 48
  EXPECT_THAT(text, HasSubstr("(3, 2): (100, 255, 100, 255) vs (100, 100, 100, 255), delta 155"));
  EXPECT_THAT(text, HasSubstr("and 1 more"));
  EXPECT_THAT(describe(compareImages(expected, expected, 0)), HasSubstr("0 of 12 pixels"));
}

TEST(ImageCompare, EmptyImagesAgreeWithoutNaN) {
  const ImageComparison c = compareImages(Image(), Image(), 0);
  EXPECT_TRUE(c.passed());
  EXPECT_EQ(c.differingShare, 0);
  EXPECT_EQ(c.meanChannelDelta, 0);
  EXPECT_THAT(describe(c), HasSubstr("0 of 0 pixels"));
}

// Pixels within the threshold: the expected colour's luma / 3 as grey; beyond it: magenta, 128 for
// the smallest delta up to 255 for delta 255.
TEST(ImageCompare, DifferenceImageGreysAgreeingPixelsAndMarksDifferingOnes) {
  Image expected = imageWith({{{0, 0}, {255, 255, 255, 255}}});
  const Image actual = imageWith({{{0, 0}, {255, 255, 255, 255}},
                                  {{1, 0}, {101, 100, 100, 255}},  // delta 1, within the threshold
                                  {{2, 0}, {100, 100, 103, 255}},  // delta 3
                                  {{3, 0}, {100, 100, 100, 255}},
                                  {{1, 1}, {255, 100, 100, 255}}});  // delta 155
  expected.at(3, 0) = {100, 100, 100, 0};                            // alpha delta 255
  const Image d = differenceImage(actual, expected, 2);
  ASSERT_EQ(d.width, 4);
  ASSERT_EQ(d.height, 3);
  EXPECT_EQ(d.at(0, 0), (Rgba{85, 85, 85, 255}));  // white dimmed to a third
  EXPECT_EQ(d.at(1, 0), (Rgba{33, 33, 33, 255}));  // grey 100 → 33.3
  EXPECT_EQ(d.at(2, 2), (Rgba{33, 33, 33, 255}));
  EXPECT_EQ(d.at(2, 0), (Rgba{129, 0, 129, 255}));  // 128 + 127·3/255 rounded
  EXPECT_EQ(d.at(3, 0), (Rgba{255, 0, 255, 255}));
  const Rgba mid = d.at(1, 1);
  EXPECT_EQ(mid.g, 0);
  EXPECT_GT(mid.r, d.at(2, 0).r);
  EXPECT_LT(mid.r, 255);
  // Every differing pixel is brighter than any agreeing one.
  EXPECT_GT(d.at(2, 0).r, d.at(0, 0).r);
}

TEST(ImageCompare, DifferenceImageOfDifferentSizesThrowsNamingBoth) {
  EXPECT_THAT(test::errorOf([] { differenceImage(Image(3, 2), Image(2, 3), 0); }),
              HasSubstr("actual 3 × 2, expected 2 × 3"));
}

}  // namespace
}  // namespace vplab
