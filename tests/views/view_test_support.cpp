#include "tests/views/view_test_support.h"

#include <string>

namespace vplab::test {

ViewFixture::ViewFixture(Scene s, Style style, int w, int h, float scale)
    : scene(std::move(s)), text(scale), width(w), height(h) {
  run = runPipeline(scene, {ClipStrategy::npc, false, true});
  settings.camera.style = style;
  settings.world = {style, defaultWorldOrbit(scene, double(w) / h)};
  settings.npc = {style, defaultNpcOrbit()};
  settings.morph = {style == Style::shaded ? Style::shaded : Style::flat, {}};
}

std::string describe(const draw::Batch& b) {
  static const char* kinds[] = {"Fill", "Lines", "Points", "Triangles", "Text"};
  const draw::Space space = std::visit(
      [](const auto& x) {
        if constexpr (requires { x.space; }) return x.space;
        else return draw::Space::pixels;
      },
      b);
  return std::string(kinds[b.index()]) + " in " + std::string(toString(space));
}

}  // namespace vplab::test
