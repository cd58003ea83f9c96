#include "app/views/display_list.h"

#include "pipeline/pipeline.h"

namespace vplab::draw {

size_t PolygonSet::polygonSize(size_t i) const {
  if (clippedNpcOf) return clippedNpcOf->clippedFace(faces[i]).size();
  return ends[i] - (i ? ends[i - 1] : 0);
}

std::span<const Vec3> PolygonSet::polygon(size_t i, std::vector<Vec3>& scratch) const {
  if (!clippedNpcOf) {
    const uint32_t begin = i ? ends[i - 1] : 0;
    return {points.data() + begin, ends[i] - begin};
  }
  scratch.clear();
  for (uint32_t ref : clippedNpcOf->clippedFace(faces[i])) scratch.push_back(clippedNpcOf->clippedNpc(ref));
  return scratch;
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
