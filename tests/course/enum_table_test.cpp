// The course's topics have one complete table (base/enum_table.h; issue 39 item 3).
#include "course/exercise.h"
#include "tests/support/enum_table_check.h"

namespace vplab {
namespace {

TEST(EnumTables, ExerciseTopicsHaveOneRowPerValueInOrder) {
  test::expectCompleteTable(kExerciseTopicNames, 4);  // orientation, mapping, clipping, pipeline
  EXPECT_EQ(fromString<ExerciseTopic>("clipping"), ExerciseTopic::clipping);
  EXPECT_EQ(toString(ExerciseTopic::pipeline), "pipeline");
}

}  // namespace
}  // namespace vplab
