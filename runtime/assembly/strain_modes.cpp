// Per-family response to homogeneous strains, from the generated tangent-vector product.
#include "assembly/strain_modes.hpp"

#include <fmt/core.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "input/yaml_keys.hpp"  // SceneError

namespace pd {

namespace {
// dy_a = eps x_a relative to the center for the symmetric unit strain
// eps = (e_r e_c^T + e_c e_r^T) / 2; dy has (L+1) d entries, the center's zero.
void unit_strain_displacement(const abi::Family& f, int d, int r, int c, std::vector<double>& dy) {
  std::fill(dy.begin(), dy.end(), 0.0);
  for (int b = 0; b < f.n_bonds; ++b) {
    const double* xi = f.xi + static_cast<std::ptrdiff_t>(b) * d;
    dy[static_cast<std::size_t>(b + 1) * d + r] += 0.5 * xi[c];
    dy[static_cast<std::size_t>(b + 1) * d + c] += 0.5 * xi[r];
  }
}
}  // namespace

StrainModeReport find_strain_blind_families(const FamilyAssembler& assembler, double tolerance) {
  const FamilyInputs& in = assembler.inputs();
  const abi::KernelVariant& variant = assembler.variant();
  const int n = in.size(), d = in.dim(), nk = d * (d + 1) / 2;
  std::vector<double> ratios(static_cast<std::size_t>(n), 1.0);
  std::vector<char> finite(static_cast<std::size_t>(n), 1);
#pragma omp parallel
  {
    FamilyGather g(in);
    std::vector<double> dy, df;
    Eigen::MatrixXd response;
#pragma omp for schedule(dynamic, 64)
    for (int p = 0; p < n; ++p) {
      const abi::Family f = g.gather(p, nullptr);
      const int m = (f.n_bonds + 1) * d;
      dy.assign(static_cast<std::size_t>(m), 0.0);
      df.assign(static_cast<std::size_t>(m), 0.0);
      response.resize(m, nk);
      int k = 0;
      for (int r = 0; r < d; ++r)
        for (int c = r; c < d; ++c, ++k) {
          unit_strain_displacement(f, d, r, c, dy);
          variant.jvp(f, dy.data(), df.data());
          for (int i = 0; i < m; ++i) response(i, k) = df[i];
        }
      // The ratio is scale-free: normalising first keeps the Gram matrix finite for large
      // but representable moduli (E = 1e200 squares to inf).
      const double scale = response.cwiseAbs().maxCoeff();
      if (!std::isfinite(scale)) {
        finite[p] = 0;
        continue;
      }
      if (scale > 0) response /= scale;
      const Eigen::VectorXd eig =
          Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(response.transpose() * response).eigenvalues();
      ratios[p] = eig[nk - 1] > 0 ? std::max(0.0, eig[0]) / eig[nk - 1] : 0.0;
    }
  }
  StrainModeReport report;
  for (int p = 0; p < n; ++p) {
    if (!finite[p]) {
      report.non_finite.push_back(p);
      continue;
    }
    if (ratios[p] < report.worst_ratio) report.worst_ratio = ratios[p], report.worst_particle = p;
    if (ratios[p] < tolerance) report.blind.push_back(p);
  }
  return report;
}

FamilyModuli family_moduli(const FamilyAssembler& assembler, int p) {
  const FamilyInputs& in = assembler.inputs();
  const int d = in.dim(), nk = d * (d + 1) / 2;
  FamilyGather g(in);
  const abi::Family f = g.gather(p, nullptr);
  const int m = (f.n_bonds + 1) * d;
  std::vector<double> dy(static_cast<std::size_t>(m)), df(static_cast<std::size_t>(m));
  FamilyModuli out{Eigen::MatrixXd::Zero(d * d, nk), Eigen::MatrixXd::Zero(d, nk)};
  int k = 0;
  for (int r = 0; r < d; ++r)
    for (int c = r; c < d; ++c, ++k) {
      unit_strain_displacement(f, d, r, c, dy);
      assembler.variant().jvp(f, dy.data(), df.data());
      for (int a = 0; a < d; ++a) out.force(a, k) = df[a] / f.V0;
      for (int b = 0; b < f.n_bonds; ++b)
        for (int a = 0; a < d; ++a)
          for (int e = 0; e < d; ++e)
            out.stress(a * d + e, k) -= df[static_cast<std::size_t>(b + 1) * d + a] * f.xi[b * d + e] / f.V0;
    }
  return out;
}

StrainModeReport check_strain_modes(const FamilyAssembler& assembler, const std::string& influence,
                                    double delta_over_h) {
  StrainModeReport report = find_strain_blind_families(assembler);
  const int n = assembler.inputs().size();
  const Particles& P = *assembler.inputs().particles;
  const auto first_five = [&P](const std::vector<int>& which) {
    std::string list;
    for (std::size_t k = 0; k < std::min<std::size_t>(which.size(), 5); ++k)
      list += fmt::format("{}particle {} at ({:.6g}, {:.6g})", k ? ", " : "", which[k],
                          P.position(which[k])[0], P.position(which[k])[1]);
    return list + (which.size() > 5 ? fmt::format(" and {} more", which.size() - 5) : "");
  };
  if (!report.non_finite.empty())  // bad input (exit 2), like a key out of range
    throw SceneError(
        fmt::format("{} of {} families give law {} an infinite or NaN response to a homogeneous strain: {}; "
                    "the law's parameters "
                    "(the material's moduli, or its `parameters`) overflow in double precision: give the "
                    "moduli in units that "
                    "make them moderate (e.g. MPa or GPa instead of Pa)",
                    report.non_finite.size(), n, assembler.law().name, first_five(report.non_finite)));
  if (2 * static_cast<long long>(report.blind.size()) > n) {
    const std::string list = first_five(report.blind);
    throw SceneError(fmt::format(  // the scene's horizon and influence: bad input (exit 2)
        "{} of {} families give law {} no stiffness against some homogeneous strain (influence {}, delta/h = "
        "{:.4g}): {}; "
        "their bonds are too few or too aligned for this law (on a square lattice, delta/h < 1.42 leaves "
        "only the axial "
        "bonds, which do not stretch under shear): increase the horizon ratio",
        report.blind.size(), n, assembler.law().name, influence, delta_over_h, list));
  }
  return report;
}

}  // namespace pd
