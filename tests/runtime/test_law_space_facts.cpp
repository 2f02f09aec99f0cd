// law_reproducing_space reads the law's descriptor, not its name (issue 28): for every law
// of the table, 2D and 3D, the space is the one law_space.cpp derived from the name's
// prefix before (its table, written out below: law_space.hpp's derivation), term by term
// and weight by weight; a renamed law keeps its space, and a law that declares none is
// refused by name.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "discretize/law_space.hpp"
#include "kernel_abi.hpp"

namespace {
struct Group {
  int lo, hi, inverse_r;
};
enum class Weight { influence, inverse_r, conical, constant };
struct Expected {
  std::vector<Group> groups;
  Weight weight;
  std::string radial;  // what the space's name says of the weight ("" : the influence's name)
};

// The definitions as law_space.cpp had them by name (commit 3c4340c): lps_paper_* K = 1/r
// built in; silling_* and lps_*: w xi^b/r^2, |b| = 3, 4; oterkus_*: those and w xi^b/r,
// |b| = 1, 2; correspondence_*: w xi^b, |b| = 1, 2; bond_based_*: c(r)/c(0) xi^b/r^3.
Expected expected_for(const std::string& law) {
  const std::vector<Group> lps{{3, 4, 2}};
  if (law.rfind("lps_paper_", 0) == 0) return {lps, Weight::inverse_r, "its built-in kernel K = 1/r"};
  if (law.rfind("silling_", 0) == 0 || law.rfind("lps_", 0) == 0) return {lps, Weight::influence, ""};
  if (law.rfind("oterkus_", 0) == 0) return {{{3, 4, 2}, {1, 2, 1}}, Weight::influence, ""};
  if (law.rfind("correspondence_", 0) == 0) return {{{1, 2, 0}}, Weight::influence, ""};
  if (law.find("conical") != std::string::npos)
    return {{{3, 4, 3}}, Weight::conical, "micromodulus 1 - r/delta"};
  return {{{3, 4, 3}}, Weight::constant, "constant micromodulus"};
}

// Every law of the table when issue 28 began.
const char* const kExistingLaws[] = {"silling_plane_strain",
                                     "silling_3d",
                                     "oterkus_plane_strain",
                                     "oterkus_3d",
                                     "oterkus_paper_d_plane_strain",
                                     "correspondence_plane_strain",
                                     "correspondence_3d",
                                     "correspondence_silling_plane_strain",
                                     "correspondence_silling_3d",
                                     "correspondence_littlewood_plane_strain",
                                     "correspondence_littlewood_3d",
                                     "bond_based_constant_2d",
                                     "bond_based_conical_2d",
                                     "bond_based_constant_3d",
                                     "bond_based_conical_3d",
                                     "lps_plane_strain",
                                     "lps_3d",
                                     "lps_corrected_plane_strain",
                                     "lps_corrected_3d",
                                     "lps_paper_plane_strain",
                                     "lps_paper_3d",
                                     "lps_paper_corrected_plane_strain",
                                     "lps_paper_corrected_3d"};

void expect_same_weight(const std::vector<pd::RadialPower>& got, const std::vector<pd::RadialPower>& want,
                        const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(got[k].coefficient, want[k].coefficient) << what << " term " << k;
    EXPECT_EQ(got[k].power, want[k].power) << what << " term " << k;
  }
}

void expect_space(const pd::ReproducingSpace& space, const std::string& law, int dim, const char* influence) {
  const Expected e = expected_for(law);
  const std::string what = law + " " + std::to_string(dim) + "D " + influence;
  std::vector<pd::BondMonomial> terms;
  for (const Group& g : e.groups) {
    const std::vector<pd::BondMonomial> t = pd::monomials(dim, g.lo, g.hi, g.inverse_r);
    terms.insert(terms.end(), t.begin(), t.end());
  }
  EXPECT_EQ(space.dim, dim) << what;
  ASSERT_EQ(space.terms.size(), terms.size()) << what;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    EXPECT_EQ(space.terms[i].powers, terms[i].powers) << what << " term " << i;
    EXPECT_EQ(space.terms[i].inverse_r_power, terms[i].inverse_r_power) << what << " term " << i;
  }
  std::vector<pd::RadialPower> weight;
  switch (e.weight) {
    case Weight::influence:
      weight = pd::influence_power_series(pd::abi::find_influence(influence)->weight, influence);
      break;
    case Weight::inverse_r:
      weight = {{1.0, -1}};
      break;
    case Weight::conical:
      weight = {{1.0, 0}, {-1.0, 1}};
      break;
    case Weight::constant:
      break;
  }
  expect_same_weight(space.weight, weight, what);
  EXPECT_EQ(space.name, law + " with " + (e.radial.empty() ? std::string(influence) : e.radial)) << what;
}
}  // namespace

TEST(LawSpaceFacts, EveryLawOfTheTableHasItsSpaceAsDerivedByName) {
  for (const char* name : kExistingLaws) ASSERT_NE(pd::abi::find_law(name), nullptr) << name;
  int checked = 0;
  for (const pd::abi::LawDescriptor& law : pd::abi::all_laws()) {
    bool existing = false;
    for (const char* name : kExistingLaws) existing = existing || law.name == std::string(name);
    if (!existing) continue;  // a law added since: its own declaration is its definition
    for (int dim : {2, 3})
      for (const char* influence : {"cubic", "inv", "const"}) {
        expect_space(
            pd::law_reproducing_space(law, dim, pd::abi::find_influence(influence)->weight, influence),
            law.name, dim, influence);
        ++checked;
      }
  }
  EXPECT_EQ(checked, 23 * 2 * 3);
}

TEST(LawSpaceFacts, CountsAsLawSpaceHppStatesThem) {
  // Silling and LPS 9 / 25, Oterkus 14 / 34, correspondence 5 / 9, bond-based 9 / 25.
  const auto count = [](const char* law, int dim) {
    return pd::law_reproducing_space(law, dim, pd::abi::find_influence("cubic")->weight, "cubic")
        .terms.size();
  };
  EXPECT_EQ(count("lps_paper_corrected_3d", 3), 25u);
  EXPECT_EQ(count("oterkus_paper_d_plane_strain", 2), 14u);
  EXPECT_EQ(count("correspondence_littlewood_3d", 3), 9u);
  EXPECT_EQ(count("bond_based_conical_2d", 2), 9u);
  EXPECT_EQ(count("bond_based_constant_3d", 3), 25u);
}

TEST(LawSpaceFacts, TheNameDoesNotDecide) {
  const auto cubic = pd::abi::find_influence("cubic")->weight;
  for (const char* name : {"oterkus_plane_strain", "bond_based_conical_2d", "lps_paper_3d"}) {
    pd::abi::LawDescriptor renamed = *pd::abi::find_law(name);
    renamed.name = "my_new_law";
    const pd::ReproducingSpace a = pd::law_reproducing_space(*pd::abi::find_law(name), 2, cubic, "cubic");
    const pd::ReproducingSpace b = pd::law_reproducing_space(renamed, 2, cubic, "cubic");
    ASSERT_EQ(a.terms.size(), b.terms.size()) << name;
    for (std::size_t i = 0; i < a.terms.size(); ++i) EXPECT_EQ(a.terms[i].powers, b.terms[i].powers) << name;
    expect_same_weight(b.weight, a.weight, name);
  }
}

TEST(LawSpaceFacts, ALawWithoutDeclaredFactsIsRefusedByName) {
  const auto cubic = pd::abi::find_influence("cubic")->weight;
  const auto message = [&](const pd::abi::LawDescriptor& law) {
    try {
      pd::law_reproducing_space(law, 2, cubic, "cubic");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  pd::abi::LawDescriptor bare = *pd::abi::find_law("silling_plane_strain");
  bare.name = "my_new_law";
  bare.n_reproducing_groups = 0;
  bare.reproducing_groups = nullptr;
  const std::string no_groups = message(bare);
  EXPECT_NE(no_groups.find("'my_new_law'"), std::string::npos) << no_groups;
  EXPECT_NE(no_groups.find("reproducing_terms"), std::string::npos) << no_groups;

  pd::abi::LawDescriptor no_kernel = *pd::abi::find_law("bond_based_constant_2d");
  no_kernel.name = "my_bond_law";
  no_kernel.n_kernel_terms = 0;
  no_kernel.kernel_terms = nullptr;
  no_kernel.kernel_description = nullptr;
  const std::string kernel = message(no_kernel);
  EXPECT_NE(kernel.find("'my_bond_law'"), std::string::npos) << kernel;
  EXPECT_NE(kernel.find("built_in_kernel"), std::string::npos) << kernel;

  const std::string unknown = [&] {
    try {
      pd::law_reproducing_space("no_such_law", 2, cubic, "cubic");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  }();
  EXPECT_NE(unknown.find("'no_such_law'"), std::string::npos) << unknown;
}
