#include "app/views/display_list.h"

namespace vplab::draw {

std::string_view toString(Space s) {
  switch (s) {
    case Space::wc: return "WC";
    case Space::npc: return "NPC";
    case Space::dc: return "DC";
    case Space::morph: return "morph";
    case Space::pixels: return "pixels";
  }
  return "?";
}

void Lines::polyline(std::span<const Vec3> points, bool closed, const glm::vec4& color) {
  if (points.size() < 2) return;
  for (size_t i = 0; i + 1 < points.size(); ++i) line(points[i], points[i + 1], color);
  if (closed && points.size() > 2) line(points.back(), points.front(), color);
}

std::vector<PlacedLabel> DisplayList::labels() const {
  std::vector<PlacedLabel> out;
  for (const Batch& b : batches)
    if (const Text* t = std::get_if<Text>(&b)) out.insert(out.end(), t->labels.begin(), t->labels.end());
  return out;
}

}  // namespace vplab::draw
