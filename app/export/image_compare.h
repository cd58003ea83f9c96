// Comparing RGBA8 images: how many pixels differ (some channel by more than a threshold), by how
// much at most and on average over all channels, and the worst pixels with their coordinates and
// both colours, plus a difference picture for the viewer's overlay and for failing golden tests.
// Our own code (no image-comparison library is used). The measures follow the idea of Magnum's
// DebugTools::CompareImage, which fails a comparison on a largest and a mean channel difference;
// callers here decide with thresholds of the same kind (the golden tests: a per-channel threshold
// and a largest share of pixels beyond it; `vplab grade image`: a mean difference and a share).
//
// Coordinates are image coordinates: x right, y down, row 0 on top (app/views/image.h, the DC
// convention of docs/conventions.md stage 5), so a reported pixel can be found in DC directly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/views/image.h"

namespace vplab {

/// One differing pixel: where it is, both colours, and its largest channel difference.
struct PixelDelta {
  int x = 0, y = 0;
  Rgba actual, expected;
  int delta = 0;  // max over r, g, b, a of |actual − expected|, 0..255
};

struct ImageComparison {
  // Both sizes, so that a mismatch can be reported (instead of compared or crashed on).
  int actualWidth = 0, actualHeight = 0;
  int expectedWidth = 0, expectedHeight = 0;
  bool sizeMismatch = false;  // then nothing below was computed

  int channelThreshold = 0;  // a pixel differs when some channel differs by more than this
  size_t pixelCount = 0;
  size_t differingPixels = 0;
  double differingShare = 0;      // differingPixels / pixelCount, 0 for empty images
  int maxChannelDelta = 0;        // over all channels (alpha included) of all pixels
  double meanChannelDelta = 0;    // mean |actual − expected| over all channels of all pixels
  std::vector<PixelDelta> worst;  // the largest deltas first; equal deltas in row-major order

  /// Same size and no pixel beyond the threshold.
  bool passed() const { return !sizeMismatch && differingPixels == 0; }
};

/// A comparison made row by row, for pictures too large to copy: `vplab grade image` compares the
/// student's picture at a shift, and against the models' flipped pictures, one row at a time
/// instead of making each picture (an 8K picture is 128 MiB). compareImages is this over every row.
class RowComparer {
 public:
  RowComparer(int width, int height, int channelThreshold, size_t worstCount = 10);
  /// Row y of both pictures, `width` pixels each; each row once, in any order.
  void add(int y, const Rgba* actual, const Rgba* expected);
  ImageComparison result() &&;

 private:
  struct Candidate {
    int delta;
    size_t index;
    Rgba actual, expected;
  };
  static bool worseThan(const Candidate& a, const Candidate& b);
  ImageComparison c_;
  size_t worstCount_;
  std::vector<Candidate> worst_;  // a heap, its top the least bad kept
  uint64_t deltaSum_ = 0;
};

/// Compares channel by channel: r, g, b and a (alpha counts like any colour channel).
/// A size mismatch is reported in the result (sizeMismatch), not thrown. Up to `worstCount`
/// differing pixels are kept in `worst`.
ImageComparison compareImages(const Image& actual, const Image& expected, int channelThreshold,
                              size_t worstCount = 10);

/// A multi-line report: the counts, the share, max and mean delta and the worst pixels with
/// coordinates and both colours; or both sizes when they differ.
std::string describe(const ImageComparison& comparison);

/// One row of the difference picture (differenceImage): `width` pixels into `out`.
void differenceRow(const Rgba* actual, const Rgba* expected, int width, int channelThreshold, Rgba* out);

/// A picture of where two images of the same size differ: pixels within the threshold as a dimmed
/// grey version of `expected` (so the scene stays recognisable), differing pixels in magenta, the
/// brighter the larger their delta. Throws vplab::Error naming both sizes when they differ.
Image differenceImage(const Image& actual, const Image& expected, int channelThreshold);

}  // namespace vplab
