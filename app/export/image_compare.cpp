#include "app/export/image_compare.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "pipeline/error.h"

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

/// A differing pixel before it is expanded into a PixelDelta: its delta and row-major index.
struct Candidate {
  int delta;
  size_t index;
};

/// Largest delta first; equal deltas in row-major order, so the report does not depend on the sort.
bool worseThan(const Candidate& a, const Candidate& b) {
  return a.delta != b.delta ? a.delta > b.delta : a.index < b.index;
}

std::vector<PixelDelta> worstPixels(std::vector<Candidate>& candidates, const Image& actual,
                                    const Image& expected, size_t count) {
  count = std::min(count, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + std::ptrdiff_t(count), candidates.end(),
                    worseThan);
  std::vector<PixelDelta> worst;
  for (size_t i = 0; i < count; ++i) {
    const size_t index = candidates[i].index;
    const int x = int(index % size_t(actual.width)), y = int(index / size_t(actual.width));
    worst.push_back({x, y, actual.pixels[index], expected.pixels[index], candidates[i].delta});
  }
  return worst;
}

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

ImageComparison compareImages(const Image& actual, const Image& expected, int channelThreshold,
                              size_t worstCount) {
  ImageComparison c;
  c.actualWidth = actual.width;
  c.actualHeight = actual.height;
  c.expectedWidth = expected.width;
  c.expectedHeight = expected.height;
  c.channelThreshold = channelThreshold;
  if (!sameSize(actual, expected)) {
    c.sizeMismatch = true;
    return c;
  }
  c.pixelCount = actual.pixels.size();
  // The worst pixels kept in a heap of `worstCount` (its top the least bad kept): memory does not
  // grow with the differing pixels (an 8K picture wholly different would take 1 GB as a list).
  std::vector<Candidate> worst;
  worst.reserve(worstCount + 1);
  uint64_t deltaSum = 0;
  size_t differing = 0;
  for (size_t i = 0; i < c.pixelCount; ++i) {
    const int delta = pixelDelta(actual.pixels[i], expected.pixels[i]);
    deltaSum += uint64_t(channelDeltaSum(actual.pixels[i], expected.pixels[i]));
    c.maxChannelDelta = std::max(c.maxChannelDelta, delta);
    if (delta <= channelThreshold) continue;
    ++differing;
    if (worstCount == 0) continue;
    const Candidate candidate{delta, i};
    if (worst.size() < worstCount) {
      worst.push_back(candidate);
      std::push_heap(worst.begin(), worst.end(), worseThan);
    } else if (worseThan(candidate, worst.front())) {
      std::pop_heap(worst.begin(), worst.end(), worseThan);
      worst.back() = candidate;
      std::push_heap(worst.begin(), worst.end(), worseThan);
    }
  }
  c.differingPixels = differing;
  if (c.pixelCount > 0) {  // an empty image has no share and no mean, not NaN
    c.differingShare = double(c.differingPixels) / double(c.pixelCount);
    c.meanChannelDelta = double(deltaSum) / (4.0 * double(c.pixelCount));
  }
  c.worst = worstPixels(worst, actual, expected, worstCount);
  return c;
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

Image differenceImage(const Image& actual, const Image& expected, int channelThreshold) {
  if (!sameSize(actual, expected))
    throw Error("cannot draw the difference of images of different sizes: actual " +
                sizeText(actual.width, actual.height) + ", expected " +
                sizeText(expected.width, expected.height));
  Image out(expected.width, expected.height);
  for (size_t i = 0; i < out.pixels.size(); ++i) {
    const int delta = pixelDelta(actual.pixels[i], expected.pixels[i]);
    if (delta > channelThreshold) {
      // Magenta from 128 (the smallest delta) to 255 (delta 255): always brighter and more saturated
      // than the grey below, whose channels stay under 86.
      const auto level = uint8_t(128 + (127 * delta + 127) / 255);
      out.pixels[i] = {level, 0, level, 255};
    } else {
      const auto grey = uint8_t(luma(expected.pixels[i]) / 3 + 0.5);
      out.pixels[i] = {grey, grey, grey, 255};
    }
  }
  return out;
}

}  // namespace vplab
