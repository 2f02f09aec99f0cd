// A scene word read straight into an enum through its names table (input/enum_names.hpp):
// the only place the scene's closed vocabularies are compared as strings. An unknown word
// fails naming the key, with the table's words in the message.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "input/enum_names.hpp"
#include "input/yaml_keys.hpp"

namespace pd {

// The word at `at` among `allowed`; otherwise at.fail(message(word)).
template <class E, class Message>
E read_word(const YamlAt& at, const std::vector<E>& allowed, Message message) {
  const std::string word = as_text(at);
  const std::optional<E> value = parse_name<E>(word);
  for (E e : allowed)
    if (value == e) return e;
  at.fail(message(word));
}

template <class E>
std::vector<E> every_value() {
  const auto all = all_of<E>();
  return std::vector<E>(all.begin(), all.end());
}

// `key: word`, required: "'word' is not one of: a, b, c" for a word outside `allowed`.
template <class E>
E enum_choice(MapReader& m, const std::string& key, const std::vector<E>& allowed) {
  return read_word(m.get(key), allowed, [&](const std::string& word) {
    return "'" + word + "' is not one of: " + name_list<E>(allowed);
  });
}

// The same with a default for a missing key.
template <class E>
E enum_choice(MapReader& m, const std::string& key, E fallback, const std::vector<E>& allowed) {
  return m.has(key) ? enum_choice(m, key, allowed) : fallback;
}

template <class E>
E enum_choice(MapReader& m, const std::string& key, E fallback) {
  return enum_choice(m, key, fallback, every_value<E>());
}

}  // namespace pd
