// The world view's handles have one complete table (base/enum_table.h; issue 39 item 3).
#include "app/inspect/picking.h"
#include "tests/support/enum_table_check.h"

#include <cstring>

namespace vplab {
namespace {

TEST(EnumTables, HandlesHaveOneRowPerValueInOrder) {
  test::expectCompleteTable(kHandleNames, 9);  // none, vrp, prp, the window's four edges, front, back
  EXPECT_STREQ(handleName(Handle::front), "front F");
  EXPECT_STREQ(handleName(Handle::none), "");
  // handleName's text goes to ImGui and into ids as a C string: it must end where the name ends.
  for (const auto& row : kHandleNames) EXPECT_EQ(std::strlen(handleName(row.value)), row.name.size());
}

}  // namespace
}  // namespace vplab
