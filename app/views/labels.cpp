// Label placement as one pass over a view (issue 37 item 4). A greedy placement in priority order
// with candidate positions around each label's point, in the manner of the cartographers' point-
// feature labelling (Imhof's positions right, above, left, below first; Christensen, Marks and
// Shieber, "An empirical study of algorithms for point-feature label placement", ACM TOG 14(3),
// 1995, found greedy placement over such candidates near the best for sparse maps, which a view's
// dozen labels are). What does not fit near its point is shortened or dropped, never stacked.
#include "app/views/labels.h"

#include <algorithm>
#include <cmath>
#include <numeric>

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

bool boxesOverlap(glm::vec2 a, glm::vec2 aSize, glm::vec2 b, glm::vec2 bSize) {
  return a.x < b.x + bSize.x && a.x + aSize.x > b.x && a.y < b.y + bSize.y && a.y + aSize.y > b.y;
}

/// Whether segment ab passes through the box [lo, hi] (Liang–Barsky's parametric clip).
bool segmentCrossesBox(glm::vec2 a, glm::vec2 b, glm::vec2 lo, glm::vec2 hi) {
  float t0 = 0, t1 = 1;
  const glm::vec2 d = b - a;
  const float p[4] = {-d.x, d.x, -d.y, d.y};
  const float q[4] = {a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const float r = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    if (t0 > t1) return false;
  }
  return true;
}

/// The places tried for a box of `size` asked at `wanted`, naming `point`: where asked, a little up
/// or down, the same on the other side of the point, then around the point (right, above, left,
/// below and the diagonals) at growing distances, nearest first.
std::vector<glm::vec2> candidates(glm::vec2 wanted, glm::vec2 size, glm::vec2 point, float gap, float reach,
                                  bool hasMarker) {
  std::vector<glm::vec2> out{wanted};
  const float steps[] = {0.6f, -0.6f, 1.1f, -1.1f};
  for (float step : steps) out.push_back(wanted + glm::vec2(0, step * size.y));
  if (hasMarker) {
    const glm::vec2 mirrored(2 * point.x - wanted.x - size.x, wanted.y);  // the same gap, left
    out.push_back(mirrored);
    for (float step : steps) out.push_back(mirrored + glm::vec2(0, step * size.y));
  }
  for (float d = gap; d <= reach; d += 0.5f * size.y) {
    const float e = d * 0.7071f;
    const glm::vec2 ring[] = {
        {point.x + d, point.y - size.y * 0.5f},           // right
        {point.x - size.x * 0.5f, point.y - d - size.y},  // above
        {point.x - d - size.x, point.y - size.y * 0.5f},  // left
        {point.x - size.x * 0.5f, point.y + d},           // below
        {point.x + e, point.y - e - size.y},              // above right
        {point.x - e - size.x, point.y - e - size.y},     // above left
        {point.x - e - size.x, point.y + e},              // below left
        {point.x + e, point.y + e},                       // below right
    };
    out.insert(out.end(), std::begin(ring), std::end(ring));
  }
  return out;
}

/// The labels placed so far and what they must keep clear of.
struct Placement {
  int width, height;
  float markerClear, labelSpace;
  std::vector<glm::vec2> markers;
  const std::vector<LabelObstacle>& obstacles;
  std::vector<PlacedLabel> placed;

  bool inside(glm::vec2 o, glm::vec2 size) const {
    return o.x >= 1 && o.y >= 1 && o.x + size.x <= float(width) - 1 && o.y + size.y <= float(height) - 1;
  }
  bool free(glm::vec2 o, glm::vec2 size) const {
    // Labels keep a space's width apart ("1back z = 0" read as one label).
    const glm::vec2 space(labelSpace);
    for (const PlacedLabel& p : placed)
      if (boxesOverlap(o - space, size + 2.f * space, p.topLeft, p.extent)) return false;
    const glm::vec2 clear(markerClear);
    for (const glm::vec2& m : markers)
      if (boxesOverlap(o, size, m - clear, 2.f * clear)) return false;
    for (const LabelObstacle& ob : obstacles)
      if (segmentCrossesBox(glm::vec2(ob.a), glm::vec2(ob.b), o, o + size)) return false;
    return true;
  }
  /// The first candidate inside the view, within reach of the point and free; none: nullopt.
  std::optional<glm::vec2> find(const TextLabel& l, glm::vec2 size, glm::vec2 point, float gap, float reach) const {
    for (const glm::vec2& c : candidates(glm::round(anchored(l, size)), size, point, gap, reach, l.marker.has_value())) {
      const glm::vec2 o = glm::round(c);
      PlacedLabel probe{o, size, {}, {}, l.size, l.shadow, point, reach};
      if (inside(o, size) && distanceToBox(probe, point) <= reach && free(o, size)) return o;
    }
    return std::nullopt;
  }
  std::vector<int> priorities;  // of each placed label
  /// Whether a label placed before says the same: about the same point, or as a more important
  /// label (a highlighted handle's name; the overlay's then says it a second time).
  bool repeats(const TextLabel& l, glm::vec2 point, float near) const {
    for (size_t i = 0; i < placed.size(); ++i)
      if (placed[i].text == l.text && (glm::distance(placed[i].anchor, point) <= near || priorities[i] > l.priority))
        return true;
    return false;
  }
  void add(PlacedLabel label, int priority) {
    placed.push_back(std::move(label));
    priorities.push_back(priority);
  }
};

}  // namespace

float distanceToBox(const PlacedLabel& label, glm::vec2 point) {
  const glm::vec2 nearest = glm::clamp(point, label.topLeft, label.topLeft + label.extent);
  return glm::distance(nearest, point);
}

std::vector<PlacedLabel> placeLabels(const std::vector<TextLabel>& labels, const TextMetrics& metrics, int width,
                                     int height, const std::vector<LabelObstacle>& obstacles) {
  const float scale = metrics.scale();
  Placement at{width, height, 7.f * scale, 3.f * scale, {}, obstacles, {}, {}};
  for (const TextLabel& l : labels)
    if (l.marker) at.markers.emplace_back(*l.marker);
  // The fixed first (they do not move), then the more important; the order given among equals.
  std::vector<size_t> order(labels.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const TextLabel &la = labels[a], &lb = labels[b];
    if (la.avoid != lb.avoid) return !la.avoid;
    return la.priority > lb.priority;
  });
  for (size_t i : order) {
    const TextLabel& l = labels[i];
    const glm::vec2 size(metrics.measure(l.text, l.size));
    if (!l.avoid) {
      const glm::vec2 o = glm::round(anchored(l, size));
      at.add({o, size, l.text, l.color, l.size, l.shadow, o, 0.f}, l.priority);
      continue;
    }
    const glm::vec2 point(l.marker ? *l.marker : l.pixel);
    // How far a label may sit from its point: 2.5 lines and the gap a marker keeps.
    const float gap = at.markerClear + 1.f, reach = 2.5f * size.y + gap;
    if (at.repeats(l, point, 2.f * gap)) continue;
    if (auto o = at.find(l, size, point, gap, reach)) {
      at.add({*o, size, l.text, l.color, l.size, l.shadow, point, reach}, l.priority);
      continue;
    }
    if (l.shortText.empty()) continue;  // no place near its point: dropped, the more important kept
    TextLabel shortened = l;
    shortened.text = l.shortText;
    const glm::vec2 shortSize(metrics.measure(shortened.text, l.size));
    if (auto o = at.find(shortened, shortSize, point, gap, reach))
      at.add({*o, shortSize, shortened.text, l.color, l.size, l.shadow, point, reach}, l.priority);
  }
  return at.placed;
}

}  // namespace vplab
