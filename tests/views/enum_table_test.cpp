// The views' enums each have one complete table (base/enum_table.h; issue 39 item 3).
#include "app/views/display_list.h"
#include "app/views/theme.h"
#include "app/views/views.h"
#include "tests/support/enum_table_check.h"

namespace vplab {
namespace {

TEST(EnumTables, ViewEnumsHaveOneRowPerValueInOrder) {
  test::expectCompleteTable(kViewKindNames, 7);     // camera, world, npc, all, morph, divideFirst, depth
  test::expectCompleteTable(kStyleNames, 5);        // flat, shaded, wire, hiddenLine, hiddenRemoved
  test::expectCompleteTable(kThemeNames, 2);        // dark, light
  test::expectCompleteTable(draw::kSpaceNames, 5);  // wc, npc, dc, morph, pixels
}

TEST(EnumTables, ViewNamesAreTheCommandLinesOwn) {
  EXPECT_EQ(toString(ViewKind::depth), "depth-plot");
  EXPECT_EQ(fromString<Style>("hidden-removed"), Style::hiddenRemoved);
  EXPECT_EQ(fromString<Theme>("light"), Theme::light);
  EXPECT_EQ(fromString<Theme>("Light"), std::nullopt);
  EXPECT_EQ(toString(draw::Space::dc), "DC");
  static_assert(kViewKindCount == 7 && allOf<Style>().size() == 5);
}

}  // namespace
}  // namespace vplab
