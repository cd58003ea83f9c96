// The depth plot's display list (lecture notes 15.2.4): the NPC-z curve runs from (B, 0) to (F, 1) in
// the plot's pixels and rises monotonically, GL's window depth is its mirror, the bars span the
// objects' VRC z ranges, and the labels stay inside the chart without overlapping.
#include "app/views/depth_plot.h"
#include "base/error.h"
#include "pipeline/view_mapping.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

namespace vplab {
namespace {

using namespace draw;

// The curves' batches: frame and ticks (1 px), GL's window depth (1.5 px), NPC z (2 px), × scale.
const Lines& linesOfWidth(const DisplayList& list, float width) {
  for (const Lines* l : test::batchesOf<Lines>(list))
    if (l->widthPx == width) return *l;
  throw std::runtime_error("no lines " + std::to_string(width) + " px wide");
}

TEST(DepthPlot, NpcZRunsFromBackAtZeroToFrontAtOneAndRises) {
  for (float scale : {1.f, 2.f}) {
    SCOPED_TRACE(scale);
    const test::ViewFixture f(defaultScene(), Style::flat, 400, 300, scale);
    const DepthPlot plot = depthPlot(f.run, 400, 240, f.text);
    const Camera& c = f.run.camera;
    // (B, 0) is the plot's bottom-left corner and (F, 1) its top-right one.
    EXPECT_EQ(plot.at(c.back, 0), glm::vec2(plot.plot.min.x, plot.plot.max.y));
    EXPECT_EQ(plot.at(c.front, 1), glm::vec2(plot.plot.max.x, plot.plot.min.y));
    const Lines& npc = linesOfWidth(plot.list, 2.f * scale);
    ASSERT_EQ(npc.space, Space::pixels);
    ASSERT_GE(npc.segments.size(), 2 * 100u);
    const glm::vec2 first(npc.segments.front().position), last(npc.segments.back().position);
    EXPECT_NEAR(first.x, plot.plot.min.x, 1e-3);
    EXPECT_NEAR(first.y, plot.plot.max.y, 1e-3);
    EXPECT_NEAR(last.x, plot.plot.max.x, 1e-3);
    EXPECT_NEAR(last.y, plot.plot.min.y, 1e-3);
    // A polyline from left to right, rising (y decreasing) all the way: NPC z grows with VRC z.
    for (size_t i = 0; i + 1 < npc.segments.size(); i += 2) {
      const Vec3 a = npc.segments[i].position, b = npc.segments[i + 1].position;
      EXPECT_LT(a.x, b.x) << "segment " << i / 2;
      EXPECT_GT(a.y, b.y) << "segment " << i / 2;
      if (i + 2 < npc.segments.size()) {
        EXPECT_EQ(b, npc.segments[i + 2].position);
      }
    }
    // Half way between B and F in VRC the curve is below half way up: perspective bends it
    // (the ticks crowd at B), the point plotted is NPC z of the middle.
    const double mid = (c.back + c.front) / 2, d = npcDepthOfVrcZ(c, f.run.vrc, mid);
    EXPECT_LT(d, 0.5);
    EXPECT_NEAR(plot.at(mid, d).y, plot.plot.max.y - d * (plot.plot.max.y - plot.plot.min.y), 1e-3);
    // GL's window depth 1 − z: dashed (every other segment of the same steps), from (B, 1) down,
    // the NPC curve mirrored in the plot's middle.
    const Lines& gl = linesOfWidth(plot.list, 1.5f * scale);
    ASSERT_EQ(gl.segments.size(), npc.segments.size() / 2);
    EXPECT_NEAR(gl.segments.front().position.x, plot.plot.min.x, 1e-3);
    EXPECT_NEAR(gl.segments.front().position.y, plot.plot.min.y, 1e-3);
    for (size_t j = 0; j < gl.segments.size(); ++j) {
      const Vec3 mirrored = npc.segments[2 * j].position;
      EXPECT_NEAR(gl.segments[j].position.x, mirrored.x, 1e-3) << j;
      EXPECT_NEAR(gl.segments[j].position.y, plot.plot.min.y + plot.plot.max.y - mirrored.y, 1e-3) << j;
    }
  }
}

// One bar per object in its colour, from its nearest-to-B to its nearest-to-F vertex (cut to the
// plot), each in its own row under the axis.
TEST(DepthPlot, BarsSpanEachObjectsVrcZ) {
  const test::ViewFixture f(defaultScene(), Style::flat);
  const DepthPlot plot = depthPlot(f.run, 400, 240, f.text);
  ASSERT_EQ(plot.bars.size(), f.run.objects.size());
  const auto triangles = test::batchesOf<Triangles>(plot.list);
  ASSERT_EQ(triangles.size(), 1u);
  ASSERT_EQ(triangles[0]->vertices.size(), 6 * plot.bars.size());
  for (size_t k = 0; k < plot.bars.size(); ++k) {
    const ObjectRun& o = f.run.objects[k];
    const DepthPlot::Bar& bar = plot.bars[k];
    EXPECT_EQ(bar.name, o.name);
    double lo = 1e300, hi = -1e300;
    for (uint32_t v = 0; v < o.vertexCount(); ++v) {
      lo = std::min(lo, o.vrc(v).z);
      hi = std::max(hi, o.vrc(v).z);
    }
    EXPECT_EQ(bar.lo, lo);
    EXPECT_EQ(bar.hi, hi);
    const Camera& c = f.run.camera;
    EXPECT_EQ(bar.bar.min.x, std::round(plot.at(std::clamp(lo, c.back, c.front), 0).x));
    EXPECT_EQ(bar.bar.max.x, std::max(std::round(plot.at(std::clamp(hi, c.back, c.front), 0).x), bar.bar.min.x + 2));
    EXPECT_GE(bar.bar.max.x, bar.bar.min.x + 2);
    EXPECT_GE(bar.row.min.y, plot.axis.max.y);
    if (k) {
      EXPECT_GE(bar.row.min.y, plot.bars[k - 1].row.max.y);
    }
    EXPECT_LE(bar.row.max.y, float(plot.list.height));
    EXPECT_EQ(triangles[0]->vertices[6 * k].color, glm::vec4(glm::vec3(o.color), 0.9f));
  }
}

// Every label inside the chart and off every other one, at any width the inspector gives it and at
// the lecture mode's scale; the names of the bars are in their rows.
TEST(DepthPlot, LabelsStayInsideAndApart) {
  for (float scale : {1.f, 1.6f, 2.f})
    for (int width : {int(130 * scale), int(260 * scale), 400, 900}) {  // the panel: at least ten lines wide
      SCOPED_TRACE(std::to_string(width) + " px at scale " + std::to_string(scale));
      const test::ViewFixture f(defaultScene(), Style::flat, width, 300, scale);
      const DepthPlot plot = depthPlot(f.run, width, int(16 * 13 * scale), f.text, {true, true});
      const std::vector<PlacedLabel> labels = plot.list.labels();
      std::set<std::string> texts;
      for (const PlacedLabel& l : labels) texts.insert(l.text);
      for (const char* t : {"— NPC z", "1", "0"}) EXPECT_EQ(texts.count(t), 1u) << t;
      EXPECT_GE(labels.size(), 2 + 2 + 2 + plot.bars.size()) << "legend, 0 and 1, B and F, bars";
      for (const PlacedLabel& l : labels) {
        EXPECT_GE(l.topLeft.x, 0) << l.text;
        EXPECT_GE(l.topLeft.y, 0) << l.text;
        EXPECT_LE(l.topLeft.x + l.extent.x, float(width)) << l.text;
        EXPECT_LE(l.topLeft.y + l.extent.y, float(plot.list.height)) << l.text;
      }
      for (size_t i = 0; i < labels.size(); ++i)
        for (size_t j = i + 1; j < labels.size(); ++j) {
          const PlacedLabel &a = labels[i], &b = labels[j];
          const bool apart = a.topLeft.x + a.extent.x <= b.topLeft.x || b.topLeft.x + b.extent.x <= a.topLeft.x ||
                             a.topLeft.y + a.extent.y <= b.topLeft.y || b.topLeft.y + b.extent.y <= a.topLeft.y;
          EXPECT_TRUE(apart) << '"' << a.text << "\" and \"" << b.text << '"';
        }
      for (const DepthPlot::Bar& bar : plot.bars) {
        bool found = false;
        for (const PlacedLabel& l : labels)
          found |= l.text == bar.name && l.topLeft.y >= bar.row.min.y - 0.5f &&  // placed labels are rounded
                   l.topLeft.y + l.extent.y <= bar.row.max.y + 0.5f;
        EXPECT_TRUE(found) << bar.name;
      }
    }
}

// `vplab render --view depth-plot`: the chart fills the requested size.
TEST(DepthPlot, ViewFillsItsSize) {
  const test::ViewFixture f(defaultScene(), Style::flat, 640, 480);
  const DisplayList list = depthPlotView(f.input());
  EXPECT_EQ(list.width, 640);
  EXPECT_EQ(list.height, 480);
  const DepthPlot plot = depthPlot(f.run, 640, 480 - int(std::ceil(depthPlotExtraHeight(f.run, 640, f.text, {true, true}))), f.text,
                                   {true, true});
  EXPECT_LE(plot.list.height, 480);
  EXPECT_GE(plot.list.height, 479);
  EXPECT_THROW(depthPlot(f.run, 4, 100, f.text), Error);
  EXPECT_THROW(depthPlot(f.run, 100, 7, f.text), Error);
  // It looks at its own pixels: the observer maps each pixel to itself (a backend drawing the
  // observer's space through the observer's camera puts the chart where it belongs).
  EXPECT_EQ(list.observer.space, Space::pixels);
  for (const Vec3& p : {Vec3(0, 0, 0.5), Vec3(640, 480, 0.5), Vec3(123.5, 47.25, 0.5)}) {
    const Projected q = projectToPixels(list.observer.camera, p, 640, 480);
    EXPECT_TRUE(q.visible);
    EXPECT_NEAR(glm::length(q.pixel - Vec2(p)), 0, 1e-9);
  }
}

}  // namespace
}  // namespace vplab
