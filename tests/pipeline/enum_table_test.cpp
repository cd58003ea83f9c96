// The pipeline's enums each have one complete table (base/enum_table.h; issue 39 item 3).
#include "pipeline/camera.h"
#include "pipeline/pipeline.h"
#include "pipeline/scene.h"
#include "tests/support/enum_table_check.h"

namespace vplab {
namespace {

TEST(EnumTables, PipelineEnumsHaveOneRowPerValueInOrder) {
  test::expectCompleteTable(kProjectionNames, 3);    // perspective, parallel, oblique
  test::expectCompleteTable(kClipStrategyNames, 3);  // npc, wc, divideFirst
  test::expectCompleteTable(kFateNames, 4);          // accepted, rejected, clipped, clippedAway
  test::expectCompleteTable(kShapeNames, 6);         // cube, tetrahedron, cylinder, sphere, polygon, mesh
}

TEST(EnumTables, NamesAreTheFormatsOwn) {
  // The names files and links already hold: a renamed row would break every saved scene and link.
  EXPECT_EQ(toString(ClipStrategy::divideFirst), "divide-first");
  EXPECT_EQ(toString(Fate::clippedAway), "clipped_away");
  EXPECT_EQ(fromString<Projection>("oblique"), Projection::oblique);
  EXPECT_EQ(fromString<Shape>("tetrahedron"), Shape::tetrahedron);
  EXPECT_EQ(fromString<ClipStrategy>("Divide-First"), std::nullopt);
  static_assert(allOf<ClipStrategy>().size() == 3 && allOf<ClipStrategy>()[2] == ClipStrategy::divideFirst);
}

}  // namespace
}  // namespace vplab
