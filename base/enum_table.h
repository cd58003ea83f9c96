// One table per enum (issue 39 item 3): each value once, with the name it has in files, links and on
// the command line. toString, the …FromString parsers and the kAll… lists (the command line's choices,
// the keys' cycles, arrays indexed by value) all read the table, so a new value is one new row.
//
//   enum class Projection { perspective, parallel, oblique };
//   inline constexpr EnumTable<Projection, 3> kProjectionNames = {{
//       {Projection::perspective, "perspective"}, {Projection::parallel, "parallel"}, {Projection::oblique, "oblique"}}};
//   inline constexpr auto kAllProjections = valuesOf(kProjectionNames);
//   inline std::string_view toString(Projection p) { return nameIn(kProjectionNames, p); }
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace vplab {

/// A value of an enum and its name.
template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

/// The rows of an enum's table, in the enum's order.
template <class E, std::size_t N>
using EnumTable = std::array<EnumName<E>, N>;

/// Every value of `table`, in its order.
template <class E, std::size_t N>
constexpr std::array<E, N> valuesOf(const EnumTable<E, N>& table) {
  std::array<E, N> values{};
  for (std::size_t i = 0; i < N; ++i) values[i] = table[i].value;
  return values;
}

/// The name of `value` in `table`; "?" for a value without a row (a cast from a number).
template <class E, std::size_t N>
constexpr std::string_view nameIn(const EnumTable<E, N>& table, E value) {
  for (const EnumName<E>& row : table)
    if (row.value == value) return row.name;
  return "?";
}

/// The value named `name` in `table` (exactly, case included), if any.
template <class E, std::size_t N>
constexpr std::optional<E> valueIn(const EnumTable<E, N>& table, std::string_view name) {
  for (const EnumName<E>& row : table)
    if (row.name == name) return row.value;
  return std::nullopt;
}

}  // namespace vplab
