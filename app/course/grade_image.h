// `vplab grade image` (issue 14): a student's screenshot against the reference rendered headless at
// the student's size, with max/mean thresholds, a difference image, and the image mistake models:
// upside down (y not flipped), mirrored (x flipped), divide first (the divide-first wrap-around,
// Hill 7.4: the CPU's divide-first polygons rasterized by app/export/cpu_raster.h).
#pragma once
#include "app/export/image_compare.h"
#include "app/render/view_renderer.h"
#include "pipeline/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace vplab {

struct ImageThresholds {
  int maxDiff = 48;          // a pixel is wrong when a channel differs by more than this (0..255)
  double meanDiff = 2.0;     // the mean channel difference over the image may be at most this
  double maxShare = 0.005;   // at most this share of the pixels may be wrong (edges rasterized differently)
  bool passes(const ImageComparison& c) const {
    return !c.sizeMismatch && c.meanChannelDelta <= meanDiff && c.differingShare <= maxShare;
  }
};

struct ImageModelResult {
  std::string key, description, hint;
  ImageComparison comparison;  // the student against the model's picture
  bool matches = false;
};

struct ImageGrade {
  ImageThresholds thresholds;
  ImageComparison comparison;   // the student against the reference
  Image reference, difference;
  std::vector<ImageModelResult> models;  // the models whose picture differs from the reference
  std::optional<size_t> mistake;         // index into models: the best matching one
  bool passed() const { return thresholds.passes(comparison); }
};

/// Renders the reference (view and style, at the student's size, the scene's device set to it so
/// the camera view stays pixel-aligned with DC) and compares. Throws vplab::Error.
ImageGrade gradeImage(ViewRenderer& renderer, const Scene& scene, const Image& student, ViewKind view, Style style,
                      const ImageThresholds& thresholds);

}  // namespace vplab
