// What the views' tests share: text measured without a font (so the tests need neither GL nor
// ImGui), a scene's run and settings as `vplab render` makes them, and a look at a list's batches.
#pragma once

#include "app/views/views.h"

#include <string_view>
#include <vector>

namespace vplab::test {

/// Every character 7 px wide (titles 10), lines 13 px high (titles 18), all × scale.
class FixedMetrics : public TextMetrics {
 public:
  explicit FixedMetrics(float scale = 1.f) : scale_(scale) {}
  Vec2 measure(std::string_view text, TextSize size) const override {
    const double w = size == TextSize::title ? 10 : 7, h = size == TextSize::title ? 18 : 13;
    return Vec2(w * double(text.size()), h) * double(scale_);
  }
  float scale() const override { return scale_; }

 private:
  float scale_;
};

/// A scene with its run (edges clipped, as the viewer's) and the settings of `vplab render`.
struct ViewFixture {
  Scene scene;
  PipelineRun run;
  DisplaySettings settings;
  Highlights highlights;
  FixedMetrics text;
  int width, height;
  ViewFixture(Scene s, Style style, int w = 400, int h = 300, float scale = 1.f);
  ViewInput input() const { return {scene, run, settings, highlights, width, height, text}; }
};

template <class B>
std::vector<const B*> batchesOf(const draw::DisplayList& list) {
  std::vector<const B*> out;
  for (const draw::Batch& b : list.batches)
    if (const B* p = std::get_if<B>(&b)) out.push_back(p);
  return out;
}

/// The end points of the segments the batch draws, its runs' edges worked out (Lines::segmentsInto).
inline std::vector<draw::Vertex> segmentsOf(const draw::Lines& l) {
  std::vector<draw::Vertex> out;
  l.segmentsInto(0, l.segmentCount(), out);
  return out;
}

/// The batch's kind and space, for messages.
std::string describe(const draw::Batch& b);

}  // namespace vplab::test
