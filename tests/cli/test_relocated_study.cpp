// `pd study` draws its plots with the script shipped beside the binary (../share/pdgen/),
// not with one in the source tree it was built from: a pd copied elsewhere with its share/
// directory plots, and one copied without it says what is missing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_pd.hpp"

namespace fs = std::filesystem;

TEST(RelocatedStudy, PlotsWithTheScriptBesideTheBinaryAndNamesItWhenMissing) {
  const fs::path root = pdtest::fresh_directory("relocated");
  fs::create_directories(root / "bin");
  const fs::path pd = root / "bin" / "pd";
  fs::copy_file(PD_EXE, pd);
  const fs::path study = root / "tiny.yaml";
  std::ofstream(study)
      << "problems: [" << PD_SOURCE_SCENES << "/uniaxial.yaml]\n"
      << "laws: [silling_plane_strain]\ninfluences: [cubic]\nratios: [3.0]\ncounts: [6, 8]\n";
  const fs::path out = root / "out";

  const auto bare = pdtest::run_pd({"study", study.string(), "--out", out.string()}, {}, pd.string());
  ASSERT_EQ(bare.status, 0) << bare.err;
  const std::string expected = (root / "share" / "pdgen" / "plot_study.py").string();
  EXPECT_NE(bare.out.find("no plots: " + expected + " is missing"), std::string::npos) << bare.out;
  EXPECT_FALSE(fs::exists(out / "uniaxial_convergence.png"));
  // Progress: the first of the two points' lines ends with an ETA for the other, the last with none.
  const auto first = bare.out.find("[1/2]"), second = bare.out.find("[2/2]");
  ASSERT_NE(second, std::string::npos) << bare.out;
  EXPECT_NE(bare.out.substr(first, second - first).find(", ETA "), std::string::npos) << bare.out;
  EXPECT_EQ(bare.out.substr(second, bare.out.find('\n', second) - second).find("ETA"), std::string::npos)
      << bare.out;

  fs::create_directories(root / "share" / "pdgen");
  fs::copy_file(PD_PLOT_SCRIPT, root / "share" / "pdgen" / "plot_study.py");
  const auto plotted = pdtest::run_pd({"study", study.string(), "--out", out.string()}, {}, pd.string());
  ASSERT_EQ(plotted.status, 0) << plotted.err;
  EXPECT_EQ(plotted.out.find("no plots"), std::string::npos) << plotted.out;
  EXPECT_TRUE(fs::exists(out / "uniaxial_convergence.png")) << plotted.out;
  fs::remove_all(root);
}
