#include "app/export/image_compare.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "base/error.h"

namespace vplab {

namespace {

int channelDelta(uint8_t a, uint8_t b) { return std::abs(int(a) - int(b)); }

/// The largest of the four channel differences: the pixel differs when it exceeds the threshold.
int pixelDelta(const Rgba& a, const Rgba& b) {
  return std::max(
      {channelDelta(a.r, b.r), channelDelta(a.g, b.g), channelDelta(a.b, b.b), channelDelta(a.a, b.a)});
}

int channelDeltaSum(const Rgba& a, const Rgba& b) {
  return channelDelta(a.r, b.r) + channelDelta(a.g, b.g) + channelDelta(a.b, b.b) + channelDelta(a.a, b.a);
}

std::string sizeText(int width, int height) { return std::to_string(width) + " × " + std::to_string(height); }

bool sameSize(const Image& a, const Image& b) { return a.width == b.width && a.height == b.height; }

std::string colorText(const Rgba& c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%d, %d, %d, %d)", c.r, c.g, c.b, c.a);
  return buf;
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

/// Rec. 601 luma, the usual "grey version" of a colour.
double luma(const Rgba& c) { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b; }

}  // namespace

RowComparer::RowComparer(int width, int height, int channelThreshold, size_t worstCount) : worstCount_(worstCount) {
  c_.actualWidth = c_.expectedWidth = width;
  c_.actualHeight = c_.expectedHeight = height;
  c_.channelThreshold = channelThreshold;
  c_.pixelCount = size_t(std::max(width, 0)) * size_t(std::max(height, 0));
  worst_.reserve(worstCount + 1);
}

/// Largest delta first; equal deltas in row-major order, so the report does not depend on the sort.
bool RowComparer::worseThan(const Candidate& a, const Candidate& b) {
  return a.delta != b.delta ? a.delta > b.delta : a.index < b.index;
}

void RowComparer::add(int y, const Rgba* actual, const Rgba* expected) {
  // The worst pixels kept in a heap of `worstCount` (its top the least bad kept): memory does not
  // grow with the differing pixels (an 8K picture wholly different would take 1 GB as a list).
  const size_t rowStart = size_t(y) * size_t(c_.actualWidth);
  for (int x = 0; x < c_.actualWidth; ++x) {
    const int delta = pixelDelta(actual[x], expected[x]);
    deltaSum_ += uint64_t(channelDeltaSum(actual[x], expected[x]));
    c_.maxChannelDelta = std::max(c_.maxChannelDelta, delta);
    if (delta <= c_.channelThreshold) continue;
    ++c_.differingPixels;
    if (worstCount_ == 0) continue;
    const Candidate candidate{delta, rowStart + size_t(x), actual[x], expected[x]};
    if (worst_.size() < worstCount_) {
      worst_.push_back(candidate);
      std::push_heap(worst_.begin(), worst_.end(), worseThan);
    } else if (worseThan(candidate, worst_.front())) {
      std::pop_heap(worst_.begin(), worst_.end(), worseThan);
      worst_.back() = candidate;
      std::push_heap(worst_.begin(), worst_.end(), worseThan);
    }
  }
}

ImageComparison RowComparer::result() && {
  if (c_.pixelCount > 0) {  // an empty image has no share and no mean, not NaN
    c_.differingShare = double(c_.differingPixels) / double(c_.pixelCount);
    c_.meanChannelDelta = double(deltaSum_) / (4.0 * double(c_.pixelCount));
  }
  std::sort(worst_.begin(), worst_.end(), worseThan);
  for (const Candidate& w : worst_)
    c_.worst.push_back({int(w.index % size_t(c_.actualWidth)), int(w.index / size_t(c_.actualWidth)), w.actual,
                        w.expected, w.delta});
  return std::move(c_);
}

ImageComparison compareImages(const Image& actual, const Image& expected, int channelThreshold,
                              size_t worstCount) {
  if (!sameSize(actual, expected)) {
    ImageComparison c;
    c.actualWidth = actual.width;
    c.actualHeight = actual.height;
    c.expectedWidth = expected.width;
    c.expectedHeight = expected.height;
    c.channelThreshold = channelThreshold;
    c.sizeMismatch = true;
    return c;
  }
  RowComparer rows(actual.width, actual.height, channelThreshold, worstCount);
  for (int y = 0; y < actual.height; ++y)
    rows.add(y, &actual.pixels[size_t(y) * size_t(actual.width)], &expected.pixels[size_t(y) * size_t(expected.width)]);
  return std::move(rows).result();
}

std::string describe(const ImageComparison& c) {
  if (c.sizeMismatch)
    return "the images differ in size: actual " + sizeText(c.actualWidth, c.actualHeight) + ", expected " +
           sizeText(c.expectedWidth, c.expectedHeight) + "\n";
  std::ostringstream text;
  text << c.differingPixels << " of " << c.pixelCount << " pixels (" << fixed(100 * c.differingShare, 4)
       << " %) differ by more than " << c.channelThreshold << " in some channel; max channel delta "
       << c.maxChannelDelta << ", mean channel delta " << fixed(c.meanChannelDelta, 4) << "\n";
  if (!c.worst.empty()) {
    text << "worst pixels (x, y): actual (r, g, b, a) vs expected, delta\n";
    for (const PixelDelta& p : c.worst)
      text << "  (" << p.x << ", " << p.y << "): " << colorText(p.actual) << " vs " << colorText(p.expected)
           << ", delta " << p.delta << "\n";
    if (c.differingPixels > c.worst.size())
      text << "  … and " << c.differingPixels - c.worst.size() << " more\n";
  }
  return text.str();
}

void differenceRow(const Rgba* actual, const Rgba* expected, int width, int channelThreshold, Rgba* out) {
  for (int x = 0; x < width; ++x) {
    const int delta = pixelDelta(actual[x], expected[x]);
    if (delta > channelThreshold) {
      // Magenta from 128 (the smallest delta) to 255 (delta 255): always brighter and more saturated
      // than the grey below, whose channels stay under 86.
      const auto level = uint8_t(128 + (127 * delta + 127) / 255);
      out[x] = {level, 0, level, 255};
    } else {
      const auto grey = uint8_t(luma(expected[x]) / 3 + 0.5);
      out[x] = {grey, grey, grey, 255};
    }
  }
}

Image differenceImage(const Image& actual, const Image& expected, int channelThreshold) {
  if (!sameSize(actual, expected))
    throw Error("cannot draw the difference of images of different sizes: actual " +
                sizeText(actual.width, actual.height) + ", expected " +
                sizeText(expected.width, expected.height));
  Image out(expected.width, expected.height);
  for (int y = 0; y < out.height; ++y) {
    const size_t row = size_t(y) * size_t(out.width);
    differenceRow(&actual.pixels[row], &expected.pixels[row], out.width, channelThreshold, &out.pixels[row]);
  }
  return out;
}

}  // namespace vplab
