#include "app/views/labels.h"

#include <algorithm>

namespace vplab {

namespace {

glm::vec2 anchored(const TextLabel& l, const glm::vec2& size) {
  glm::vec2 at(l.pixel);
  switch (l.anchor) {
    case Anchor::topLeft: break;
    case Anchor::center: at -= size * 0.5f; break;
    case Anchor::left: at.y -= size.y * 0.5f; break;
    case Anchor::bottomLeft: at.y -= size.y; break;
    case Anchor::topCenter: at.x -= size.x * 0.5f; break;
  }
  return at;
}

}  // namespace

std::vector<PlacedLabel> placeLabels(const std::vector<TextLabel>& labels, const TextMetrics& metrics, int width,
                                     int height) {
  const float markerClearPx = 7.f * metrics.scale();
  std::vector<PlacedLabel> out;
  std::vector<glm::vec2> markers;
  for (const TextLabel& l : labels)
    if (l.marker) markers.emplace_back(*l.marker);
  for (const TextLabel& l : labels) {
    const glm::vec2 size(metrics.measure(l.text, l.size));
    const glm::vec2 lo(2.f), hi = glm::max(glm::vec2(2.f), glm::vec2(width, height) - size - 2.f);
    const glm::vec2 wanted = glm::clamp(glm::round(anchored(l, size)), lo, hi);
    auto overlaps = [&](glm::vec2 o) {
      for (const PlacedLabel& p : out) {
        const glm::vec2 r0 = p.topLeft, r1 = p.topLeft + p.extent;
        if (o.x < r1.x && o.x + size.x > r0.x && o.y < r1.y && o.y + size.y > r0.y) return true;
      }
      for (const glm::vec2& m : markers)
        if (o.x < m.x + markerClearPx && o.x + size.x > m.x - markerClearPx && o.y < m.y + markerClearPx &&
            o.y + size.y > m.y - markerClearPx)
          return true;
      return false;
    };
    // Greedy: the wanted place, else near it (up or down by up to two lines, then the same on the
    // other side of its marker), so a label never strays far from its point; when all overlap,
    // the wanted place after all.
    std::vector<glm::vec2> candidates{wanted};
    const float steps[] = {0.6f, -0.6f, 1.1f, -1.1f, 1.7f, -1.7f, 2.3f, -2.3f};
    for (float step : steps) candidates.push_back(wanted + glm::vec2(0, step * size.y));
    if (l.marker) {
      const glm::vec2 mirrored(2 * float(l.marker->x) - wanted.x - size.x, wanted.y);  // the same gap, left
      candidates.push_back(mirrored);
      for (float step : steps) candidates.push_back(mirrored + glm::vec2(0, step * size.y));
    }
    glm::vec2 origin = wanted;
    if (l.avoid)
      for (const glm::vec2& c : candidates) {
        const glm::vec2 clamped = glm::round(glm::clamp(c, lo, hi));
        if (!overlaps(clamped)) {
          origin = clamped;
          break;
        }
      }
    out.push_back({origin, size, l.text, l.color, l.size, l.shadow});
  }
  return out;
}

}  // namespace vplab
