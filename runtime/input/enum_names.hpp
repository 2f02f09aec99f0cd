// The scene's closed vocabularies: each enum's words in one names table (enum_names<E>::table),
// the single source of its spellings. name_of prints a value (logs, summary.json, messages),
// parse_name reads a word, name_list lists the words for an error message; the scene reader
// reads words through input/enum_choice.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace pd {

template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

// Specialised next to each enum: `static constexpr std::array<EnumName<E>, N> table{...}`, in
// the order error messages list the words.
template <class E>
struct enum_names;

template <class E>
constexpr std::string_view name_of(E value) {
  for (const EnumName<E>& n : enum_names<E>::table)
    if (n.value == value) return n.name;
  return "?";
}

template <class E>
constexpr std::optional<E> parse_name(std::string_view word) {
  for (const EnumName<E>& n : enum_names<E>::table)
    if (n.name == word) return n.value;
  return std::nullopt;
}

// The words of `values` joined by ", " (the last by `last`, e.g. " or ").
template <class E, class Values>
std::string name_list(const Values& values, std::string_view last = ", ") {
  std::string out;
  std::size_t i = 0;
  for (E e : values) {
    if (i > 0) out += i + 1 == std::size(values) ? last : std::string_view(", ");
    out += name_of(e);
    ++i;
  }
  return out;
}

// Every value of E, in the table's order.
template <class E>
constexpr auto all_of() {
  std::array<E, enum_names<E>::table.size()> values{};
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = enum_names<E>::table[i].value;
  return values;
}

template <class E>
std::string name_list(std::string_view last = ", ") {
  return name_list<E>(all_of<E>(), last);
}

}  // namespace pd
