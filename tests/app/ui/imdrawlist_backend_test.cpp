// The ImDrawList backend (app/ui/imdrawlist_backend.h): a display list's 2D batches become ImGui
// primitives at an offset, clipped to the list's rectangle; 3D or depth-tested batches are refused.
// An ImGui context without a renderer (no GL): only the draw lists it records are looked at.
#include "app/ui/imdrawlist_backend.h"
#include "app/views/depth_plot.h"

#include <gtest/gtest.h>

#include <imgui.h>

#include <stdexcept>

namespace vplab {
namespace {

using namespace draw;

class ImDrawListBackend : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // as the viewer: nothing written into the working directory
    io.DisplaySize = ImVec2(800, 600);
    unsigned char* pixels;
    int w, h;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(800, 600));
    ImGui::Begin("test");
    dl_ = ImGui::GetWindowDrawList();
  }
  void TearDown() override {
    ImGui::End();
    ImGui::EndFrame();
    ImGui::DestroyContext();
  }
  ImDrawList* dl_ = nullptr;
};

DisplayList pixelList(int w, int h) {
  DisplayList list;
  list.width = w;
  list.height = h;
  list.observer.space = Space::pixels;
  return list;
}

// Triangles keep each vertex's colour, at the origin's offset; the list's rectangle is the clip rect.
TEST_F(ImDrawListBackend, TrianglesAtTheOffsetInTheirVertexColours) {
  DisplayList list = pixelList(100, 50);
  Triangles t;
  t.space = Space::pixels;
  t.triangle({0, 0, 0}, {100, 0, 0}, {0, 50, 0}, {1, 0, 0, 1});
  t.vertices[1].color = {0, 1, 0, 1};
  t.vertices[2].color = {0, 0, 1, 0.5f};
  list.add(std::move(t));
  const int before = dl_->VtxBuffer.Size;
  ui::drawDisplayList(*dl_, list, ImVec2(20, 60));
  ASSERT_EQ(dl_->VtxBuffer.Size, before + 3);
  const ImDrawVert* v = dl_->VtxBuffer.Data + before;
  EXPECT_EQ(v[0].pos.x, 20.f);
  EXPECT_EQ(v[0].pos.y, 60.f);
  EXPECT_EQ(v[1].pos.x, 120.f);
  EXPECT_EQ(v[2].pos.y, 110.f);
  EXPECT_EQ(v[0].col, IM_COL32(255, 0, 0, 255));
  EXPECT_EQ(v[1].col, IM_COL32(0, 255, 0, 255));
  EXPECT_EQ(v[2].col, IM_COL32(0, 0, 255, 128));
  // The command holding them is clipped to the list's rectangle (within the window's).
  const ImDrawCmd* drawn = nullptr;  // the last command with elements (popping the clip rect began another)
  for (const ImDrawCmd& c : dl_->CmdBuffer)
    if (c.ElemCount > 0) drawn = &c;
  ASSERT_NE(drawn, nullptr);
  const ImVec4 clip = drawn->ClipRect;
  EXPECT_EQ(clip.x, 20.f);
  EXPECT_EQ(clip.y, 60.f);
  EXPECT_EQ(clip.z, 120.f);
  EXPECT_EQ(clip.w, 110.f);
}

TEST_F(ImDrawListBackend, RefusesWhatNeedsADepthBufferOrACamera) {
  const int clipRects = dl_->_ClipRectStack.Size;
  DisplayList fill = pixelList(10, 10);
  fill.add(Fill{});
  EXPECT_THROW(ui::drawDisplayList(*dl_, fill, ImVec2(0, 0)), std::invalid_argument);
  DisplayList wc = pixelList(10, 10);
  Lines l;
  l.space = Space::wc;
  l.line({0, 0, 0}, {1, 1, 1}, {1, 1, 1, 1});
  wc.add(l);
  EXPECT_THROW(ui::drawDisplayList(*dl_, wc, ImVec2(0, 0)), std::invalid_argument);
  DisplayList tested = pixelList(10, 10);
  l.space = Space::pixels;
  l.depth = Depth::test;
  tested.add(l);
  EXPECT_THROW(ui::drawDisplayList(*dl_, tested, ImVec2(0, 0)), std::invalid_argument);
  // The clip rect pushed for the list is popped even so.
  EXPECT_EQ(dl_->_ClipRectStack.Size, clipRects);
}

// The depth plot measured with ImGui's font: its labels are ImGui's text (the width of each is
// CalcTextSize's), and drawing it adds glyphs, lines and the bars inside the chart's rectangle.
TEST_F(ImDrawListBackend, DrawsTheDepthPlotWithImGuisFont) {
  const ui::ImGuiTextMetrics text(1.f);
  EXPECT_EQ(text.measure("B = -3.2", TextSize::label).x, ImGui::CalcTextSize("B = -3.2").x);
  EXPECT_EQ(text.measure("B = -3.2", TextSize::label).y, ImGui::CalcTextSize("B = -3.2").y);
  const PipelineRun run = runPipeline(defaultScene());
  const DepthPlot plot = depthPlot(run, 380, 200, text);
  const int before = dl_->VtxBuffer.Size;
  const ImVec2 origin(30, 40);
  ui::drawDisplayList(*dl_, plot.list, origin);
  size_t labelChars = 0;
  for (const PlacedLabel& l : plot.list.labels()) labelChars += l.text.size();
  // Each line segment is a quad of at least 4 vertices, each glyph one of 4.
  EXPECT_GT(dl_->VtxBuffer.Size - before, int(4 * (120 + 60 + labelChars / 2)));
  for (int i = before; i < dl_->VtxBuffer.Size; ++i) {
    const ImVec2 p = dl_->VtxBuffer[i].pos;
    EXPECT_GE(p.x, origin.x - 2) << i;  // lines reach half their width (and their 1 px fringe) beyond their ends
    EXPECT_GE(p.y, origin.y - 2) << i;
    EXPECT_LE(p.x, origin.x + float(plot.list.width) + 2) << i;
    EXPECT_LE(p.y, origin.y + float(plot.list.height) + 2) << i;
  }
}

}  // namespace
}  // namespace vplab
