// A display list's bytes (draw::memoryUse, `vplab bench --memory`): each kind of batch against the
// list's own contents, counted here.
#include "pipeline/primitives.h"
#include "tests/views/view_test_support.h"
#include "tests/support/memory_use_support.h"

#include <gtest/gtest.h>

#include <memory>

namespace vplab {
namespace {

using namespace draw;

using test::bytesOf;

// The wire style's world view: the clipped edges by reference (Lines::runEdges), which the "lines" part
// counts without the segments they stand for; the labels and batches as held.
TEST(DisplayListMemory, LinesPolygonsAndLabelsAreCountedFromTheList) {
  Scene scene = defaultScene();  // a sphere's 8 000 edges: far more than the view's own lines
  scene.objects[0].shape = Shape::sphere;
  scene.objects[0].segments = 64;
  scene.objects[0].mesh = std::make_shared<const Mesh>(sphere(64));
  test::ViewFixture wire(scene, Style::wire);
  const DisplayList list = worldView(wire.input());
  size_t own = 0, refs = 0, drawn = 0, labels = 0;
  for (const Lines* l : test::batchesOf<Lines>(list)) {
    own += l->segments.size();
    refs += l->runEdges.size();
    drawn += l->segmentCount();
  }
  for (const Text* t : test::batchesOf<Text>(list)) labels += t->labels.size();
  ASSERT_GT(refs, 0u);
  ASSERT_GT(labels, 0u);
  const MemoryUse use = memoryUse(list);
  EXPECT_GE(bytesOf(use, "lines"), own * sizeof(Vertex) + refs * sizeof(RunEdges));
  EXPECT_LT(bytesOf(use, "lines"), 2 * drawn * sizeof(Vertex)) << "the edges were copied";
  EXPECT_GE(bytesOf(use, "labels"), labels * sizeof(PlacedLabel));
  EXPECT_GE(bytesOf(use, "batches"), list.batches.size() * sizeof(Batch));

  test::ViewFixture shaded(defaultScene(), Style::shaded);
  // The NPC view's clipped polygons: points or, by reference, face numbers.
  const DisplayList npc = npcView(shaded.input());
  size_t polygonBytes = 0;
  for (const Fill* fill : test::batchesOf<Fill>(npc))
    for (const PolygonSet& p : fill->polygons) polygonBytes += p.points.size() * sizeof(Vec3) + p.faces.size() * 4;
  EXPECT_GE(bytesOf(memoryUse(npc), "polygons"), polygonBytes);
}

}  // namespace
}  // namespace vplab
