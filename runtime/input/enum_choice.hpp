// A scene word read straight into an enum: the only place the solver's and the
// dynamics' method names are compared as strings (every value E has name_of(E) and
// all_values<E>::values).
#pragma once

#include <string>
#include <vector>

#include "input/yaml_keys.hpp"

namespace pd {

template <class E>
E enum_choice(MapReader& m, const std::string& key, E fallback) {
  std::vector<std::string> allowed;
  for (E e : all_values<E>::values) allowed.emplace_back(name_of(e));
  const std::string word = m.choice(key, std::string(name_of(fallback)), allowed);
  for (E e : all_values<E>::values)
    if (word == name_of(e)) return e;
  return fallback;  // unreachable: choice() accepts only the allowed words
}

}  // namespace pd
