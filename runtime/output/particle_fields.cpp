// Field validation shared by the writers.
#include "output/particle_fields.hpp"

#include <set>
#include <stdexcept>

namespace pd {

void check_output_fields(std::span<const OutputField> fields, int n) {
  std::set<std::string> names;
  for (const OutputField& f : fields) {
    if (f.name.empty()) throw std::invalid_argument("output field without a name");
    if (!names.insert(f.name).second)
      throw std::invalid_argument("output field '" + f.name + "' given twice");
    if (f.components < 1 || f.components > 9)
      throw std::invalid_argument("output field '" + f.name + "': bad component count");
    if (f.values.size() != static_cast<std::size_t>(n) * f.components)
      throw std::invalid_argument("output field '" + f.name + "' has " + std::to_string(f.values.size()) +
                                  " values for " + std::to_string(n) + " particles x " +
                                  std::to_string(f.components));
  }
}

}  // namespace pd
