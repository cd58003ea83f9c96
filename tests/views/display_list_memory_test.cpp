// A display list's bytes (draw::memoryUse, `vplab bench --memory`): each kind of batch against the
// list's own contents, counted here.
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

namespace vplab {
namespace {

using namespace draw;

size_t bytesOf(const MemoryUse& use, const std::string& name) {
  for (const MemoryPart& p : use)
    if (p.name == name) return p.bytes;
  ADD_FAILURE() << "no part named " << name;
  return 0;
}

// The wire style's world view: every clipped edge as line segments, which the "lines" part holds at
// least; the shaded style draws the meshes by reference, with far fewer bytes of lines.
TEST(DisplayListMemory, LinesPolygonsAndLabelsAreCountedFromTheList) {
  test::ViewFixture wire(defaultScene(), Style::wire);
  const DisplayList list = worldView(wire.input());
  size_t segments = 0, labels = 0;
  for (const Lines* l : test::batchesOf<Lines>(list)) segments += l->segments.size();
  for (const Text* t : test::batchesOf<Text>(list)) labels += t->labels.size();
  ASSERT_GT(segments, 0u);
  ASSERT_GT(labels, 0u);
  const MemoryUse use = memoryUse(list);
  EXPECT_GE(bytesOf(use, "lines"), segments * sizeof(Vertex));
  EXPECT_GE(bytesOf(use, "labels"), labels * sizeof(PlacedLabel));
  EXPECT_GE(bytesOf(use, "batches"), list.batches.size() * sizeof(Batch));

  test::ViewFixture shaded(defaultScene(), Style::shaded);
  EXPECT_LT(bytesOf(memoryUse(worldView(shaded.input())), "lines"), bytesOf(use, "lines"));

  // The NPC view's clipped polygons: points or, by reference, face numbers.
  const DisplayList npc = npcView(shaded.input());
  size_t polygonBytes = 0;
  for (const Fill* fill : test::batchesOf<Fill>(npc))
    for (const PolygonSet& p : fill->polygons) polygonBytes += p.points.size() * sizeof(Vec3) + p.faces.size() * 4;
  EXPECT_GE(bytesOf(memoryUse(npc), "polygons"), polygonBytes);
}

}  // namespace
}  // namespace vplab
