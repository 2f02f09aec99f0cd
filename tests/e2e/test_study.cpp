// The quick sweep of studies/constant_strain.yaml: the orders it fits must agree in sign
// with the full-sweep conclusions (paper 000 section 5.2, reproduced by the full sweep):
// the deformation-gradient law converges on all three problems, Silling's law converges
// on biaxial compression only, Oterkus's on simple shear; Silling's does not converge on
// shear. (Our Oterkus also converges on biaxial compression, unlike the paper's: see
// docs/paper000.md.) Also checks the cache: a second run reads every point from disk.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "study/study.hpp"

TEST(Study, FitOrderRecoversAPowerLaw) {
  const std::vector<double> h{0.4, 0.2, 0.1, 0.05}, e{3 * std::pow(0.4, 1.7), 3 * std::pow(0.2, 1.7), 3 * std::pow(0.1, 1.7), -1};
  int used = 0;
  EXPECT_NEAR(pd::fit_order(h, e, &used), 1.7, 1e-12);
  EXPECT_EQ(used, 3);  // the non-positive error is skipped
  EXPECT_TRUE(std::isnan(pd::fit_order({0.1}, {0.2})));
}

TEST(Study, QuickSweepReachesTheFullSweepConclusions) {
  const auto spec = pd::read_study(std::string(PD_SOURCE_DIR) + "/studies/constant_strain.yaml");
  const std::string out = testing::TempDir() + "/pd_study_quick";
  std::filesystem::remove_all(out);
  int lines = 0;
  const auto orders = pd::run_study(spec, out, true, [&](const std::string&) { ++lines; });
  auto order = [&](const char* problem, const char* law, double ratio) {
    for (const auto& o : orders)
      if (o.problem == problem && o.law == law && o.ratio == ratio) return o.order;
    ADD_FAILURE() << "no series " << problem << " " << law << " " << ratio;
    return std::nan("");
  };
  for (double ratio : {1.5, 3.0}) {
    for (const char* problem : {"uniaxial", "biaxial", "shear"}) EXPECT_GT(order(problem, "correspondence_plane_strain", ratio), 0.8);
    EXPECT_GT(order("biaxial", "silling_plane_strain", ratio), 0.8);
    EXPECT_GT(order("shear", "oterkus_plane_strain", ratio), 0.8);
    EXPECT_LT(order("shear", "silling_plane_strain", ratio), 0.2);
  }
  EXPECT_LT(order("uniaxial", "silling_plane_strain", 1.5), 0.3);
  EXPECT_TRUE(std::filesystem::exists(out + "/points.csv"));
  EXPECT_TRUE(std::filesystem::exists(out + "/orders.md"));
  // Resume: every point now comes from the cache, with identical orders.
  const auto again = pd::run_study(spec, out, true, [](const std::string&) {});
  ASSERT_EQ(again.size(), orders.size());
  for (std::size_t i = 0; i < orders.size(); ++i)
    if (std::isfinite(orders[i].order)) EXPECT_NEAR(again[i].order, orders[i].order, 1e-6);
}
