// The enumerations of the C ABI whose values run 0 .. count - 1 (B2B_CURVE_*,
// B2B_END_*, B2B_LAW_*, B2B_TANGENT_*). Each has one table in the library,
// an entry per value in value order (src/curve/kinds.hpp,
// src/pair/laws.hpp, ...), and the C API's checks and messages read the
// table through an Enumeration, so that a new value is one new entry.
#pragma once

#include <cstddef>

namespace b2b {

// The value of an enumerator and its name, from the one token: an entry's
// name cannot drift from the header's spelling, and a misspelt name does not
// compile.
#define B2B_NAMED(enumerator) (enumerator), #enumerator

// The entry of an enumeration that has nothing but a name (B2B_END_*,
// B2B_TANGENT_*): {B2B_NAMED(enumerator)}.
struct NamedValue {
  int value;
  const char* name;
};

// What a check and its message need of an enumeration: how many values,
// and the names of the first and the last.
struct Enumeration {
  int count = 0;
  const char* first = "";
  const char* last = "";

  constexpr bool contains(int value) const { return value >= 0 && value < count; }
};

// The Enumeration of a table whose entries have a `name`.
template <class Entry, std::size_t N>
constexpr Enumeration enumeration_of(const Entry (&table)[N]) {
  return Enumeration{static_cast<int>(N), table[0].name, table[N - 1].name};
}

// True if entry i of the table has the value i (its `value`), for every i:
// the table lists the enumeration in value order, without gaps.
template <class Entry, std::size_t N>
constexpr bool in_value_order(const Entry (&table)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (table[i].value != static_cast<int>(i)) return false;
  return true;
}

// True if every entry's internal id (an enum class) has the entry's public
// value: the table and the internal enumeration agree.
template <class Entry, std::size_t N>
constexpr bool ids_match_values(const Entry (&table)[N]) {
  for (const Entry& e : table)
    if (static_cast<int>(e.id) != e.value) return false;
  return true;
}

}  // namespace b2b
