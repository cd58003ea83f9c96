// One table per enum (issue 39 item 3): each value once, with the name it has in files, links and on
// the command line. toString, the …FromString parsers and the kAll… lists (the command line's choices,
// the keys' cycles, arrays indexed by value) all read the table, so a new value is one new row.
//
//   enum class Projection { perspective, parallel, oblique };
//   inline constexpr EnumTable<Projection, 3> kProjectionNames = {{
//       {Projection::perspective, "perspective"}, {Projection::parallel, "parallel"}, {Projection::oblique, "oblique"}}};
//   inline constexpr auto allOf<Projection>() = valuesOf(kProjectionNames);
//   inline std::string_view toString(Projection p) { return nameIn(kProjectionNames, p); }
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <type_traits>

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

/// An enum with a table: namesOf(value), declared beside the enum, returns it.
template <class E>
concept NamedEnum = std::is_enum_v<E> && requires(E e) { namesOf(e); };

/// The name of `value` (the table's row; "?" for a value without one).
template <NamedEnum E>
constexpr std::string_view toString(E value) {
  return nameIn(namesOf(value), value);
}

/// The value of E named `name` (exactly, case included), if any.
template <NamedEnum E>
constexpr std::optional<E> fromString(std::string_view name) {
  return valueIn(namesOf(E{}), name);
}

/// Every value of E, in the enum's order.
template <NamedEnum E>
constexpr auto allOf() {
  return valuesOf(namesOf(E{}));
}

}  // namespace vplab
