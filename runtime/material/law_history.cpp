#include "material/law_history.hpp"

namespace pd {

namespace {
std::string names(const char* const* list, int n, const char* where) {
  if (n == 0) return "";
  std::string out;
  for (int i = 0; i < n; ++i) out += (i ? ", " : "") + std::string(list[i]);
  return out + " per " + where;
}
}  // namespace

std::string describe_history(const abi::LawDescriptor& law) {
  const std::string bond = names(law.history_names, law.n_history, "bond");
  const std::string particle = names(law.particle_history_names, law.n_particle_history, "particle");
  return bond.empty() ? particle : particle.empty() ? bond : bond + "; " + particle;
}

}  // namespace pd
