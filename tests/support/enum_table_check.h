// Checks one enum's table (base/enum_table.h) against what the enum is: a row for every value,
// in the enum's order (values 0, 1, …: so arrays indexed by value and the keys' cycles line up), names
// unique, every name read back to its value, and namesOf(E) handing over this table. `count` is the enum's number of values, written
// in the test from the enum's declaration, not taken from the table.
#pragma once

#include "base/enum_table.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace vplab::test {

template <class E, std::size_t N>
void expectCompleteTable(const EnumTable<E, N>& table, std::size_t count) {
  ASSERT_EQ(N, count) << "the table has " << N << " rows, the enum " << count << " values";
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < N; ++i) {
    EXPECT_EQ(static_cast<std::size_t>(table[i].value), i) << "row " << i << " (" << table[i].name << ") is out of the enum's order";
    EXPECT_TRUE(names.insert(table[i].name).second) << "the name \"" << table[i].name << "\" stands twice";
    EXPECT_EQ(nameIn(table, E(i)), table[i].name);
    const std::optional<E> back = valueIn(table, table[i].name);
    ASSERT_TRUE(back.has_value()) << table[i].name;
    EXPECT_EQ(*back, E(i)) << table[i].name;
    // toString, fromString<E> and allOf<E> read this very table (namesOf(E) hands it over).
    EXPECT_EQ(toString(E(i)), table[i].name);
    EXPECT_EQ(fromString<E>(table[i].name), std::optional<E>(E(i)));
    EXPECT_EQ(allOf<E>()[i], E(i));
  }
  EXPECT_EQ(&namesOf(E{}), &table) << "namesOf hands over another table";
  EXPECT_EQ(nameIn(table, E(N)), "?") << "a value past the table has no name";
  EXPECT_FALSE(valueIn(table, std::string_view("no such name")).has_value());
  if (N > 0 && !table[0].name.empty()) {  // case matters: "NPC" is not "npc"
    std::string upper(table[0].name);
    for (char& c : upper) c = (c >= 'a' && c <= 'z') ? char(c - 32) : (c >= 'A' && c <= 'Z') ? char(c + 32) : c;
    if (upper != table[0].name) {
      EXPECT_NE(valueIn(table, upper), std::optional<E>(table[0].value)) << upper;
    }
  }
}

}  // namespace vplab::test
