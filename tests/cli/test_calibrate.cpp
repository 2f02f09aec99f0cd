// pd calibrate (issue 33): the fit recovers the parameters a field was made with, from
// noise-free data, to 1e-8 relative -- E and nu of a plane-stress plate, the field written by
// pd run at other values (scenes/calibration_plate.yaml, scenes/calibration_truth.yaml) -- and bad input
// exits 2 naming what is wrong: a parameter the material does not have, bounds that exclude the start, a
// field point outside the body, a field without displacement columns.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "run_pd.hpp"

namespace {

struct Fixture {
  std::filesystem::path dir;
  Fixture() : dir(pdtest::fresh_directory("calibrate")) {
    std::filesystem::copy_file(std::string(PD_SOURCE_SCENES) + "/calibration_plate.yaml", dir / "plate.yaml");
    std::filesystem::copy_file(std::string(PD_SOURCE_SCENES) + "/calibration_truth.yaml", dir / "truth.yaml");
    const pdtest::PdResult r = pdtest::run_pd({"run", "truth.yaml"}, dir);
    EXPECT_EQ(r.status, 0) << r.err;
  }
};
}  // namespace

TEST(PdCalibrate, RecoversTheParametersOfNoiseFreeData) {
  Fixture f;
  const pdtest::PdResult r =
      pdtest::run_pd({"calibrate", "plate.yaml", "--data", "out/calibration_truth/result.csv", "--fit",
                      "E=50:500", "--fit", "nu=0:0.45"},
                     f.dir);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const nlohmann::json j = nlohmann::json::parse(pdtest::slurp(f.dir / "out/calibration/calibration.json"));
  EXPECT_TRUE(j["converged"].get<bool>());
  EXPECT_NEAR(j["parameters"][0]["fitted"].get<double>(), 170.0, 1e-8 * 170.0);
  EXPECT_NEAR(j["parameters"][1]["fitted"].get<double>(), 0.22, 1e-8 * 0.22);
  EXPECT_GT(j["forward_solves"].get<int>(), 1);
  // The fitted scene solves to the data.
  const pdtest::PdResult again = pdtest::run_pd({"run", "out/calibration/fitted.yaml"}, f.dir);
  EXPECT_EQ(again.status, 0) << again.err;
}

TEST(PdCalibrate, BadInputExitsTwoNamingTheProblem) {
  Fixture f;
  const auto expect_refused = [&](std::vector<std::string> args, const std::string& says) {
    args.insert(args.begin(), {"calibrate", "plate.yaml"});
    const pdtest::PdResult r = pdtest::run_pd(args, f.dir);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  };
  expect_refused({"--data", "out/calibration_truth/result.csv", "--fit", "sigma_y"},
                 "no parameter 'sigma_y'");
  expect_refused({"--data", "out/calibration_truth/result.csv", "--fit", "steel.E"}, "no material 'steel'");
  expect_refused({"--data", "out/calibration_truth/result.csv", "--fit", "E=300:500"}, "outside its bounds");
  std::ofstream(f.dir / "beyond.csv") << "x,y,u_x\n0.1,0.1,0\n5.0,0.5,1e-3\n";
  expect_refused({"--data", "beyond.csv", "--fit", "E"}, "beyond.csv:3: row 2: no particle within h/2");
  std::ofstream(f.dir / "no_u.csv") << "x,y,ux\n0.1,0.1,0\n";
  expect_refused({"--data", "no_u.csv", "--fit", "E"}, "no_u.csv:1: no displacement column");
}
