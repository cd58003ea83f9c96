#include "app/ui/imdrawlist_backend.h"

#include <imgui_internal.h>  // ImDrawListSharedData::TexUvWhitePixel

#include <cmath>
#include <stdexcept>
#include <string>

namespace vplab::ui {

namespace {

using namespace draw;

ImU32 color32(const glm::vec4& c) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)); }

void refuse(const char* what, Space space, Depth depth) {
  if (space == Space::pixels && depth == Depth::ignore) return;
  throw std::invalid_argument(std::string("the ImDrawList backend draws 2D batches only: ") + what + " in " +
                              std::string(toString(space)) +
                              (depth == Depth::ignore ? "" : ", depth-tested"));
}

struct Drawer {
  ImDrawList& dl;
  ImVec2 origin;

  ImVec2 at(const Vec3& p) const { return ImVec2(origin.x + float(p.x), origin.y + float(p.y)); }

  void operator()(const Fill&) const {
    throw std::invalid_argument("the ImDrawList backend draws 2D batches only: a fill (faces need a depth buffer)");
  }

  // Wide lines; dashes dashPx on, dashPx off from each segment's start (as the GL backend's).
  void operator()(const Lines& l) const {
    refuse("lines", l.space, l.depth);
    if (!l.meshEdges.empty()) refuse("mesh edges", Space::wc, l.depth);
    if (!l.runEdges.empty()) refuse("a run's edges", Space::wc, l.depth);
    for (size_t i = 0; i + 1 < l.segments.size(); i += 2) {
      const ImVec2 a = at(l.segments[i].position), b = at(l.segments[i + 1].position);
      const ImU32 col = color32(l.segments[i].color);
      if (l.dashPx <= 0) {
        dl.AddLine(a, b, col, l.widthPx);
        continue;
      }
      const float length = std::hypot(b.x - a.x, b.y - a.y);
      for (float s = 0; s < length; s += 2 * l.dashPx) {
        const float e = std::min(length, s + l.dashPx);
        dl.AddLine(ImLerp(a, b, s / length), ImLerp(a, b, e / length), col, l.widthPx);
      }
    }
  }

  // Round markers with a dark rim.
  void operator()(const Points& p) const {
    refuse("points", p.space, p.depth);
    const float r = p.sizePx * 0.5f, rim = std::max(1.f, p.sizePx * 0.12f);
    for (const Vertex& v : p.points) {
      dl.AddCircleFilled(at(v.position), r, color32({0, 0, 0, 0.8f * v.color.a}));
      dl.AddCircleFilled(at(v.position), r - rim, color32(v.color));
    }
  }

  // Triangles in their vertices' colours (ImDrawList's primitives with its white texel).
  void operator()(const Triangles& t) const {
    refuse("triangles", t.space, t.depth);
    if (t.vertices.size() < 3) return;
    const ImVec2 uv = dl._Data->TexUvWhitePixel;
    const size_t count = t.vertices.size() / 3 * 3;
    dl.PrimReserve(int(count), int(count));
    for (size_t i = 0; i < count; ++i) {
      dl.PrimWriteIdx(ImDrawIdx(dl._VtxCurrentIdx));
      dl.PrimWriteVtx(at(t.vertices[i].position), uv, color32(t.vertices[i].color));
    }
  }

  void operator()(const Text& t) const {
    for (const PlacedLabel& l : t.labels) {
      const float size = ImGuiTextMetrics::fontSize(l.size);
      const ImVec2 p(origin.x + l.topLeft.x, origin.y + l.topLeft.y);
      if (l.shadow) dl.AddText(ImGui::GetFont(), size, ImVec2(p.x + 1, p.y + 1), color32({0, 0, 0, 0.8f * l.color.a}), l.text.c_str());
      dl.AddText(ImGui::GetFont(), size, p, color32(l.color), l.text.c_str());
    }
  }
};

}  // namespace

float ImGuiTextMetrics::fontSize(TextSize size) {
  return ImGui::GetFontSize() * (size == TextSize::title ? 4.f / 3.f : 1.f);
}

Vec2 ImGuiTextMetrics::measure(std::string_view text, TextSize size) const {
  const ImVec2 s =
      ImGui::GetFont()->CalcTextSizeA(fontSize(size), FLT_MAX, 0.f, text.data(), text.data() + text.size());
  return {std::floor(s.x + 0.99999f), s.y};  // as ImGui::CalcTextSize
}

void drawDisplayList(ImDrawList& out, const DisplayList& list, ImVec2 origin, const ImDrawListOptions& options) {
  const ImVec2 end(origin.x + float(list.width), origin.y + float(list.height));
  out.PushClipRect(origin, end, true);
  if (options.background) out.AddRectFilled(origin, end, color32(glm::vec4(list.background, 1.f)));
  const Drawer drawer{out, origin};
  try {
    for (const Batch& b : list.batches) std::visit(drawer, b);
  } catch (...) {
    out.PopClipRect();
    throw;
  }
  out.PopClipRect();
}

}  // namespace vplab::ui
