// `pd calibrate SCENE.yaml --data FIELD.csv --fit E=LO:HI [--fit nu ...] [--out DIR]`: fits
// material parameters of a static scene to a measured displacement field
// (runtime/sensitivity/calibration.hpp) and writes DIR/calibration.json and DIR/fitted.yaml.
#include <fmt/core.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "input/measured_field.hpp"
#include "input/scene.hpp"
#include "input/yaml_keys.hpp"
#include "output/atomic_file.hpp"
#include "sensitivity/calibration.hpp"

namespace pd::cli {

namespace {
struct CalibrateOptions {
  std::string scene, data, out = "out/calibration";
  std::vector<std::string> fits;
  int max_iterations = 50;
  std::string jacobian = "exact";
};

// "KEY", "KEY=LO:HI", "MATERIAL.KEY=LO:HI"; either bound may be empty (unbounded).
FitParameter parse_fit(const Scene& scene, const std::string& text) {
  const std::size_t eq = text.find('=');
  FitParameter f{parse_scene_parameter(scene, text.substr(0, eq))};
  if (eq == std::string::npos) return f;
  const std::string range = text.substr(eq + 1);
  const std::size_t colon = range.find(':');
  if (colon == std::string::npos)
    throw std::invalid_argument("--fit " + text + ": the bounds are LO:HI (either may be empty)");
  const auto bound = [&](const std::string& s, double fallback) {
    if (s.empty()) return fallback;
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || !std::isfinite(v))
      throw std::invalid_argument("--fit " + text + ": '" + s + "' is not a finite number");
    return v;
  };
  f.lower = bound(range.substr(0, colon), f.lower);
  f.upper = bound(range.substr(colon + 1), f.upper);
  if (!(f.lower < f.upper)) throw std::invalid_argument("--fit " + text + ": the bounds leave no interval");
  return f;
}

// The scene file with the fitted values in its materials (comments are not kept).
std::string fitted_yaml(const std::string& scene_path, const Scene& scene, const CalibrationResult& r) {
  YAML::Node root = YAML::LoadFile(scene_path);
  for (std::size_t j = 0; j < r.parameters.size(); ++j) {
    const SceneParameter& p = r.parameters[j].parameter;
    std::size_t m = 0;
    while (scene.materials[m].name != p.material) ++m;
    YAML::Node material = root["materials"][m];
    if (p.key == "E" || p.key == "nu")
      material[p.key] = r.fitted[j];
    else
      material["parameters"][p.key] = r.fitted[j];
  }
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << root;
  return fmt::format("# {} with the parameters fitted by pd calibrate\n{}\n", scene_path, out.c_str());
}

int run_calibration(const CalibrateOptions& o) {
  Scene scene;
  std::vector<FitParameter> fits;
  MeasuredField data;
  try {
    scene = read_scene(o.scene);
    if (scene.dynamics) throw std::invalid_argument(o.scene + ": calibration fits static scenes only");
    for (const std::string& f : o.fits) fits.push_back(parse_fit(scene, f));
    data = read_measured_field(o.data, scene.dim);
  } catch (const std::exception& e) {  // SceneError, a parameter the scene has not
    fmt::print(stderr, "pd calibrate: {}\n", e.what());
    return 2;
  }
  CalibrationResult r;
  CalibrationOptions options;
  options.max_iterations = o.max_iterations;
  if (o.jacobian == "central_differences") options.jacobian = JacobianMethod::central_differences;
  try {
    r = calibrate(scene, fits, data, options, [](const std::string& l) { fmt::print("{}\n", l); });
  } catch (const SceneError& e) {
    fmt::print(stderr, "pd calibrate: {}\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "pd calibrate: {}\n", e.what());
    return 2;
  }
  fmt::print("{:<16} {:>14} {:>22} {:>14}\n", "parameter", "start", "fitted", "std. error");
  nlohmann::json json;
  for (std::size_t j = 0; j < fits.size(); ++j) {
    fmt::print("{:<16} {:>14.6g} {:>22.15g} {:>14.3g}\n", fits[j].parameter.label(), r.initial[j],
               r.fitted[j], r.standard_error[j]);
    json["parameters"].push_back(
        {{"name", fits[j].parameter.label()},
         {"start", r.initial[j]},
         {"fitted", r.fitted[j]},
         {"standard_error",
          std::isfinite(r.standard_error[j]) ? nlohmann::json(r.standard_error[j]) : nlohmann::json(nullptr)},
         {"lower", std::isfinite(fits[j].lower) ? nlohmann::json(fits[j].lower) : nullptr},
         {"upper", std::isfinite(fits[j].upper) ? nlohmann::json(fits[j].upper) : nullptr}});
  }
  json["converged"] = r.converged;
  json["message"] = r.message;
  json["iterations"] = r.iterations;
  json["forward_solves"] = r.forward_solves;
  json["sensitivity_solves"] = r.linear_solves;
  json["residuals"] = r.residuals;
  json["rms_misfit"] = {{"initial", r.initial_rms}, {"final", r.final_rms}};
  json["scene"] = o.scene;
  json["data"] = o.data;
  std::filesystem::create_directories(o.out);
  write_file_atomically(o.out + "/fitted.yaml", fitted_yaml(o.scene, scene, r));
  write_file_atomically(o.out + "/calibration.json", json.dump(2) + "\n");
  fmt::print("{}: {}\nresults: {}/calibration.json, {}/fitted.yaml\n",
             r.converged ? "converged" : "NOT converged", r.message, o.out, o.out);
  return r.converged ? 0 : 1;
}
}  // namespace

Command add_calibrate_command(CLI::App& pd) {
  CLI::App* cmd = pd.add_subcommand("calibrate", "fit material parameters to a measured displacement field");
  cmd->footer(
      "Minimises 1/2 sum (u - measured)^2 over the field's points (each matched to the particle within\n"
      "h/2) by Ceres' bounded Levenberg-Marquardt with the exact Jacobian du/dp of the static solve.\n"
      "FIELD.csv: a header naming x, y[, z] and u_x, u_y[, u_z] (pd run's result.csv is one).\n"
      "--fit KEY[=LO:HI]: KEY is E, nu or a material parameter, MATERIAL.KEY for another material\n"
      "than the first; an empty bound is none. Writes DIR/calibration.json and DIR/fitted.yaml.\n"
      "Exit codes: 0 converged, 1 not converged or a solve failed, 2 bad usage or bad input.\n");
  auto options = std::make_shared<CalibrateOptions>();
  cmd->add_option("SCENE", options->scene, "the scene file (YAML)")->required();
  cmd->add_option("--data", options->data, "the measured field FIELD.csv")->required()->check(kNonEmptyPath);
  cmd->add_option("--fit", options->fits, "a parameter to fit, KEY[=LO:HI] (repeat for more)")->required();
  cmd->add_option("--out", options->out, "the output directory DIR")
      ->capture_default_str()
      ->check(kNonEmptyPath);
  cmd->add_option("--max-iterations", options->max_iterations, "Levenberg-Marquardt iterations at most")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--jacobian", options->jacobian,
                  "exact (the sensitivities) or central_differences (2 solves per parameter per Jacobian)")
      ->capture_default_str()
      ->check(CLI::IsMember({"exact", "central_differences"}));
  return [options] { return run_calibration(*options); };
}

}  // namespace pd::cli
