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
  int maxShift = 1;          // a picture shifted by at most this many pixels (each axis) is graded at its shift
  bool passes(const ImageComparison& c) const {
    return !c.sizeMismatch && c.meanChannelDelta <= meanDiff && c.differingShare <= maxShare;
  }
};

struct ImageModelResult {
  std::string key, description, hint;
  std::string descriptionDe, hintDe;  // the same in the lecture's German
  ImageComparison comparison;  // the student against the model's picture
  bool matches = false;
};

/// How far the student's picture is shifted against the reference: its content at (x + dx, y + dy)
/// is the reference's at (x, y). Searched within kShiftSearch pixels each way.
struct ImageShift {
  int dx = 0, dy = 0;
  bool operator==(const ImageShift&) const = default;
};
inline constexpr int kShiftSearch = 16;

struct ImageGrade {
  ImageThresholds thresholds;
  ImageShift shift;             // the best shift found (0, 0: none)
  bool shiftTolerated = true;   // |dx|, |dy| ≤ thresholds.maxShift: compared at the shift
  ImageComparison comparison;   // the student (at a tolerated shift) against the reference
  Image reference, difference;
  std::vector<ImageModelResult> models;  // the models whose picture differs from the reference
  std::optional<size_t> mistake;         // index into models: the best matching one
  bool passed() const { return shiftTolerated && thresholds.passes(comparison); }
};

/// Renders the reference (view and style, at the student's size, the scene's device set to it so
/// the camera view stays pixel-aligned with DC) and compares: at the shift that fits best when it is
/// within thresholds.maxShift (the pixels shifted in from outside count as right), else the picture
/// fails as shifted, whatever else it shows. Throws vplab::Error.
/// The shift of `student` against `reference` (same size) that makes them differ least (mean channel
/// difference over the pixels both cover), (0, 0) unless another is clearly better (half the difference).
ImageShift bestShift(const Image& student, const Image& reference);
/// `student` moved back by `shift`: its pixel (x + dx, y + dy) at (x, y); outside, the reference's.
Image unshifted(const Image& student, const Image& reference, ImageShift shift);

ImageGrade gradeImage(ViewRenderer& renderer, const Scene& scene, const Image& student, ViewKind view, Style style,
                      const ImageThresholds& thresholds);

}  // namespace vplab
