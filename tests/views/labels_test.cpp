// The label placement pass (app/views/labels.h): labels never sit on each other, stay in their view
// and by their point; a crowded label is moved, then shortened, then dropped, the less important
// first; a label never crosses an obstacle (the NPC axes); the same name for the same point is said once.
#include "app/views/labels.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

bool overlap(const PlacedLabel& a, const PlacedLabel& b) {
  return a.topLeft.x < b.topLeft.x + b.extent.x && a.topLeft.x + a.extent.x > b.topLeft.x &&
         a.topLeft.y < b.topLeft.y + b.extent.y && a.topLeft.y + a.extent.y > b.topLeft.y;
}

TextLabel at(Vec2 point, std::string text, int priority = 0, std::string shortText = {}) {
  TextLabel l{point + Vec2(8, 0), std::move(text)};
  l.marker = point;
  l.priority = priority;
  l.shortText = std::move(shortText);
  return l;
}

// Five labels asked for at almost the same point (the world view's VRP, U, V, N and VUP near each
// other): all five placed, none on another, each within reach of its point.
TEST(Labels, CrowdedLabelsMoveAroundTheirPointsAndNeverOverlap) {
  const test::FixedMetrics metrics;
  std::vector<TextLabel> labels;
  for (const char* name : {"VRP", "U", "V", "N", "VUP"}) labels.push_back(at({100, 100}, name));
  const std::vector<PlacedLabel> placed = placeLabels(labels, metrics, 300, 200);
  ASSERT_EQ(placed.size(), 5u);
  for (size_t i = 0; i < placed.size(); ++i) {
    for (size_t j = i + 1; j < placed.size(); ++j) EXPECT_FALSE(overlap(placed[i], placed[j])) << placed[i].text << " on " << placed[j].text;
    EXPECT_LE(distanceToBox(placed[i], {100, 100}), placed[i].reach) << placed[i].text;
    EXPECT_GT(distanceToBox(placed[i], {100, 100}), 0.f) << placed[i].text << " covers its point";
  }
}

// In a view too small for both, the more important label keeps its place and the other is shortened;
// with no room even for the short text, it is dropped: never stacked.
TEST(Labels, TheLessImportantIsShortenedThenDropped) {
  const test::FixedMetrics metrics;
  // A 120 × 60 view: "hintere Ebene B" (105 px) fits once beside the point, "F" below it.
  const std::vector<PlacedLabel> placed =
      placeLabels({at({5, 20}, "vordere Ebene F", 0, "F"), at({5, 20}, "hintere Ebene B", 1, "B")}, metrics, 120, 60);
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[0].text, "hintere Ebene B");
  EXPECT_EQ(placed[1].text, "F");
  EXPECT_FALSE(overlap(placed[0], placed[1]));
  const std::vector<PlacedLabel> none = placeLabels({at({5, 20}, "hintere Ebene B", 1), at({5, 20}, "vordere Ebene F")}, metrics, 120, 24);
  ASSERT_EQ(none.size(), 1u);
  EXPECT_EQ(none[0].text, "hintere Ebene B");
}

// A label that would lie across an obstacle (the NPC view's y axis under "vorne z = 1") moves off it.
TEST(Labels, NoLabelCrossesAnObstacle) {
  const test::FixedMetrics metrics;
  TextLabel front{{100, 50}, "vorne z = 1"};
  front.anchor = Anchor::center;
  const LabelObstacle yAxis{{100, 150}, {100, 10}};
  const std::vector<PlacedLabel> placed = placeLabels({front}, metrics, 300, 200, {yAxis});
  ASSERT_EQ(placed.size(), 1u);
  const PlacedLabel& l = placed[0];
  EXPECT_TRUE(l.topLeft.x >= 100 || l.topLeft.x + l.extent.x <= 100) << "the label lies across x = 100";
  EXPECT_LE(distanceToBox(l, {100, 50}), l.reach);
}

// A highlighted handle's name is said once: the overlay's "PRP" for the same point gives way.
TEST(Labels, TheSameNameIsSaidOnce) {
  const test::FixedMetrics metrics;
  const std::vector<PlacedLabel> placed = placeLabels({at({50, 50}, "PRP", 1), at({52, 50}, "PRP", 2)}, metrics, 300, 200);
  ASSERT_EQ(placed.size(), 1u);
  EXPECT_EQ(placed[0].anchor, glm::vec2(52, 50)) << "the highlighted one (priority 2) is kept";
}

// Titles and a plot's fixed labels (avoid = false) stay where asked, and the others keep off them.
TEST(Labels, FixedLabelsStayAndOthersKeepOffThem) {
  const test::FixedMetrics metrics;
  TextLabel title{{10, 10}, "t = 2.50  VRC", {1, 1, 1, 1}, TextSize::title, Anchor::topLeft, true, false};
  const std::vector<PlacedLabel> placed = placeLabels({at({20, 20}, "x"), title}, metrics, 300, 200);
  ASSERT_EQ(placed.size(), 2u);
  EXPECT_EQ(placed[0].topLeft, glm::vec2(10, 10));
  EXPECT_FALSE(overlap(placed[0], placed[1]));
}

}  // namespace
}  // namespace vplab
