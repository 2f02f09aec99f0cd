// Surface correction factors (paper 003 eq. 19), surface_correction.hpp.
#include "assembly/surface_correction.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string_view>

#include "assembly/family_gather.hpp"
#include "discretize/lattice_family.hpp"

namespace pd {

namespace {
// The trial strains, row-major dim x dim: [0] the dilatation, then an orthonormal basis of
// the traceless symmetric strains scaled to Frobenius norm sqrt 2.
std::vector<std::vector<double>> trial_strains(int d) {
  std::vector<std::vector<double>> e;
  auto zero = [&] { return std::vector<double>(static_cast<std::size_t>(d * d), 0.0); };
  auto add_diag = [&](std::vector<double> diag) {
    std::vector<double> m = zero();
    for (int c = 0; c < d; ++c) m[static_cast<std::size_t>(c * d + c)] = diag[static_cast<std::size_t>(c)];
    e.push_back(m);
  };
  add_diag(std::vector<double>(static_cast<std::size_t>(d), 1.0));
  add_diag(d == 2 ? std::vector<double>{1, -1} : std::vector<double>{1, -1, 0});
  if (d == 3) add_diag({1 / std::sqrt(3.0), 1 / std::sqrt(3.0), -2 / std::sqrt(3.0)});
  for (int a = 0; a < d; ++a)
    for (int b = a + 1; b < d; ++b) {
      std::vector<double> m = zero();
      m[static_cast<std::size_t>(a * d + b)] = m[static_cast<std::size_t>(b * d + a)] = 1.0;
      e.push_back(m);
    }
  return e;
}

// R(eps) of the family through the JVP at the reference configuration.
double response(const abi::LawDescriptor& law, const abi::Family& f, const std::vector<double>& eps,
                std::vector<double>& dy, std::vector<double>& df) {
  const int d = law.dim, L = f.n_bonds;
  dy.assign(static_cast<std::size_t>((L + 1) * d), 0.0);
  df.assign(dy.size(), 0.0);
  for (int k = 0; k < L; ++k)
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < d; ++c)
        dy[static_cast<std::size_t>((k + 1) * d + r)] +=
            eps[static_cast<std::size_t>(r * d + c)] * f.xi[k * d + c];
  law.intact.jvp(f, dy.data(), df.data());
  double R = 0;
  for (std::size_t i = 0; i < dy.size(); ++i) R -= df[i] * dy[i];
  return R / f.V0;
}

// A and B of R = s_f (A + s_d B) for both trials, and the moments the family needs.
struct Affine {
  TrialResponse A, B;
};

Affine affine_response(const abi::LawDescriptor& law, abi::Family f) {
  Affine out;
  const TrialResponse r0 = trial_response(law, f, 0.0, 1.0);
  const TrialResponse r1 = law.has_dilatation_sum ? trial_response(law, f, 1.0, 1.0) : r0;
  out.A = r0;
  out.B = {r1.dilatation - r0.dilatation, r1.deviatoric - r0.deviatoric};
  return out;
}

void set_moments(const abi::LawDescriptor& law, abi::Family& f, std::vector<double>& moments) {
  moments.assign(static_cast<std::size_t>(law.n_moments), 0.0);
  if (law.n_moments > 0) law.intact.moments(f, moments.data());
  f.moments = law.n_moments > 0 ? moments.data() : nullptr;
}
}  // namespace

TrialResponse trial_response(const abi::LawDescriptor& law, const abi::Family& family, double s_d,
                             double s_f) {
  abi::Family f = family;
  std::vector<double> Y(f.xi, f.xi + static_cast<std::ptrdiff_t>(f.n_bonds) * law.dim);
  std::vector<double> sd(static_cast<std::size_t>(f.n_bonds), s_d),
      sf(static_cast<std::size_t>(f.n_bonds), s_f);
  f.Y = Y.data(), f.dilatation_factor = sd.data(), f.force_factor = sf.data();
  std::vector<double> dy, df;
  const std::vector<std::vector<double>> strains = trial_strains(law.dim);
  TrialResponse r;
  r.dilatation = response(law, f, strains[0], dy, df);
  for (std::size_t s = 1; s < strains.size(); ++s) r.deviatoric += response(law, f, strains[s], dy, df);
  return r;
}

namespace {
// The law's dilatation of a family under the isotropic stretch Y = (1 + e) xi, or with
// axis >= 0 the uniaxial one Y = xi + e (xi . e_axis) e_axis, every bond carrying
// dilatation factor 1: the output "dilatation" (pdgen Law::dilatation_sum).
double trial_dilatation(const abi::LawDescriptor& law, const abi::Family& family, int output,
                        std::vector<double>& outs, int axis = -1, const double* bond_sd = nullptr) {
  abi::Family f = family;
  const double e = 1e-6;
  const int d = law.dim;
  std::vector<double> Y(f.xi, f.xi + static_cast<std::ptrdiff_t>(f.n_bonds) * d);
  if (axis < 0)
    for (double& y : Y) y *= 1 + e;
  else
    for (int k = 0; k < f.n_bonds; ++k) Y[static_cast<std::size_t>(k * d + axis)] *= 1 + e;
  f.Y = Y.data(), f.dilatation_factor = bond_sd, f.force_factor = nullptr;
  outs.assign(static_cast<std::size_t>(law.n_outputs), 0.0);
  law.intact.outputs(f, outs.data());
  return outs[static_cast<std::size_t>(output)] / e;
}

int dilatation_output(const abi::LawDescriptor& law) {
  for (int i = 0; i < law.n_outputs; ++i)
    if (std::string_view(law.output_names[i]) == "dilatation") return i;
  throw std::invalid_argument(
      fmt::format("law {} marks a dilatation sum but has no output 'dilatation'", law.name));
}
}  // namespace

namespace {
// eps = e_axis e_axis, row-major d x d: the uniaxial stretch along one axis.
std::vector<double> axis_stretch(int d, int axis) {
  std::vector<double> eps(static_cast<std::size_t>(d * d), 0.0);
  eps[static_cast<std::size_t>(axis * d + axis)] = 1.0;
  return eps;
}

// (sum_k (n_k / s_k)^2)^(-1/2) for n = xi / |xi|: the radius along xi of the ellipsoid
// whose semi-axes are the factors s_k (s_k for a bond along axis k; s for every bond when
// all s_k = s).
double ellipsoid_radius(const double* s, const double* xi, int d) {
  double r2 = 0, q = 0;
  for (int k = 0; k < d; ++k) r2 += xi[k] * xi[k], q += (xi[k] / s[k]) * (xi[k] / s[k]);
  return std::sqrt(r2 / q);
}

// R(e_axis e_axis) of the family, its bonds carrying the dilatation factors sd and the
// force factors sf (null: 1).
double axis_response(const abi::LawDescriptor& law, const abi::Family& family, int axis, const double* sd,
                     const double* sf = nullptr) {
  abi::Family f = family;
  std::vector<double> Y(f.xi, f.xi + static_cast<std::ptrdiff_t>(f.n_bonds) * law.dim);
  std::vector<double> ones(static_cast<std::size_t>(f.n_bonds), 1.0);
  f.Y = Y.data(), f.dilatation_factor = sd != nullptr ? sd : ones.data();
  f.force_factor = sf != nullptr ? sf : ones.data();
  std::vector<double> dy, df;
  return response(law, f, axis_stretch(law.dim, axis), dy, df);
}

// The full family's answers to each axis' stretch: theta (a law with a dilatation sum) and R.
struct AxisTrials {
  std::vector<double> theta, R;
};
AxisTrials full_axis_trials(const abi::LawDescriptor& law, const abi::Family& ff, int theta_out,
                            std::vector<double>& outs) {
  AxisTrials t;
  for (int k = 0; k < law.dim; ++k) {
    t.theta.push_back(theta_out >= 0 ? trial_dilatation(law, ff, theta_out, outs, k) : 0.0);
    t.R.push_back(axis_response(law, ff, k, nullptr));
  }
  return t;
}

// Directions: particle i's factors per axis, [dim] each, into sd and sf.
void axis_factors(const abi::LawDescriptor& law, const abi::Family& f, int theta_out, const AxisTrials& full,
                  std::vector<double>& outs, double* sd, double* sf) {
  const int d = law.dim;
  for (int k = 0; k < d; ++k)
    sd[k] = theta_out >= 0
                ? full.theta[static_cast<std::size_t>(k)] / trial_dilatation(law, f, theta_out, outs, k)
                : 1.0;
  std::vector<double> bond_sd(static_cast<std::size_t>(f.n_bonds));
  for (int b = 0; b < f.n_bonds; ++b)
    bond_sd[static_cast<std::size_t>(b)] = ellipsoid_radius(sd, f.xi + b * d, d);
  for (int k = 0; k < d; ++k)
    sf[k] = full.R[static_cast<std::size_t>(k)] / axis_response(law, f, k, bond_sd.data());
}

// Per bond of each family: one factor per particle (nc = 1), the mean of the bond's two
// ends' (paper 003 eq. 19); one per axis (directions), the family's own factors along the
// bond's direction. Not the mean there: a bond carries the mean of its ends', so a surface
// family whose neighbours inside are near 1 stays under-corrected, and Jacobi sweeps that
// make the mean rule self-consistent diverged on the 14^3 cube (linear influence, delta =
// 3h). Each family's own force states are its own (the bond i-j of family i and the bond
// j-i of family j are separate entries), so its own factors break no balance law.
std::vector<double> bond_factors(const Bonds& b, const std::vector<double>& f, int nc) {
  std::vector<double> bond(b.neighbor.size(), 1.0), ends(static_cast<std::size_t>(nc));
  for (int i = 0; i < b.particle_count(); ++i)
    for (int e = b.offsets[i]; e < b.offsets[i + 1]; ++e) {
      if (nc == 1) {
        bond[e] = 0.5 * (f[static_cast<std::size_t>(i)] + f[static_cast<std::size_t>(b.neighbor[e])]);
        continue;
      }
      for (int k = 0; k < nc; ++k)
        ends[static_cast<std::size_t>(k)] = f[static_cast<std::size_t>(i * nc + k)];
      bond[e] = ellipsoid_radius(ends.data(), &b.xi[static_cast<std::size_t>(e * nc)], nc);
    }
  return bond;
}

// Directions, made exact: the first factors take each axis' force factor with force factor
// 1 on every bond, but a bond carries the ellipsoid's radius of all the axes' factors, so
// the axes' trials are coupled. Sweeps rescale each family's factors by what its trials
// miss with the bond factors it actually carries, until the largest change is below 1e-10
// (about 50 sweeps on the cube; refused after 200). Families are independent here (their
// own factors, bond_factors), so each converges on its own.
void make_self_consistent(const abi::LawDescriptor& law, const Bonds& b, FamilyGather& gather,
                          const std::vector<const AxisTrials*>& full, int theta_out, SurfaceFactors& s) {
  const int n = b.particle_count(), d = s.components;
  std::vector<double> outs, moments;
  for (int sweep = 0; sweep < 200; ++sweep) {
    const std::vector<double> bsd = bond_factors(b, s.dilatation, d), bsf = bond_factors(b, s.force, d);
    double change = 0;
    for (int i = 0; i < n; ++i) {
      const double* sd = bsd.data() + b.offsets[i];
      const double* sf = bsf.data() + b.offsets[i];
      abi::Family f = gather.gather(i, nullptr);
      f.dilatation_factor = sd, f.force_factor = sf;  // as the assembler will see the family
      set_moments(law, f, moments);
      for (int k = 0; k < d; ++k) {
        const auto c = static_cast<std::size_t>(i * d + k);
        const AxisTrials& F = *full[static_cast<std::size_t>(i)];
        const double rd = theta_out >= 0 ? F.theta[static_cast<std::size_t>(k)] /
                                               trial_dilatation(law, f, theta_out, outs, k, sd)
                                         : 1.0;
        const double rf = F.R[static_cast<std::size_t>(k)] / axis_response(law, f, k, sd, sf);
        s.dilatation[c] *= rd, s.force[c] *= rf;
        change = std::max({change, std::abs(rd - 1), std::abs(rf - 1)});
      }
    }
    if (change < 1e-8) return;
  }
  throw std::runtime_error(fmt::format(
      "surface correction (directions): the factors of law {} did not settle in 200 sweeps", law.name));
}

void check_factors(const SurfaceCorrectionInputs& in, int i, double sd, double sf) {
  if (sd > 0 && sf > 0 && std::isfinite(sd) && std::isfinite(sf)) return;
  const abi::LawDescriptor& law = *in.law;
  throw std::runtime_error(fmt::format(
      "surface correction ({}): particle {} gives dilatation factor {:.6g} and force factor {:.6g} (law "
      "{}): not positive numbers{}",
      surface_match_name(in.match), i, sd, sf, law.name,
      in.match == SurfaceMatch::Responses && law.has_dilatation_sum
          ? "; matching both responses needs a dilatation term that moves the two trials differently (for "
            "the "
            "dilatation laws it vanishes near Poisson ratio 1/4 in plane strain): use match terms"
          : ""));
}
}  // namespace

SurfaceFactors surface_correction_factors(const Particles& p, const Bonds& b,
                                          const SurfaceCorrectionInputs& in) {
  const abi::LawDescriptor& law = *in.law;
  if (law.intact.jvp == nullptr)
    throw std::invalid_argument(
        fmt::format("law {} has no JVP kernel: the surface correction evaluates the trial "
                    "responses through it",
                    law.name));
  const int theta_out = law.has_dilatation_sum ? dilatation_output(law) : -1;
  const int n = p.size();
  LatticeFamily full(in.quadrature, in.delta, in.h, p.dim, in.influence, 0.0, law.scratch_per_bond);
  std::vector<double> moments, outs;
  struct Interior {
    TrialResponse R;
    double theta = 0;
    AxisTrials axes;  // directions only
  };
  const bool directions = in.match == SurfaceMatch::Directions;
  const int nc = directions ? p.dim : 1;
  std::vector<const AxisTrials*> full_axes(directions ? static_cast<std::size_t>(n) : 0);
  std::map<std::pair<int, double>, Interior> interior;  // (material, V0) -> the full family's trials
  FamilyInputs fi;
  fi.particles = &p, fi.bonds = &b, fi.params = *in.params, fi.scratch_per_bond = law.scratch_per_bond;
  FamilyGather gather(fi);
  SurfaceFactors out{nc, std::vector<double>(static_cast<std::size_t>(n * nc), 1.0),
                     std::vector<double>(static_cast<std::size_t>(n * nc), 1.0)};
  for (int i = 0; i < n; ++i) {
    const int mat = p.material[i];
    const double* params = (*in.params)[static_cast<std::size_t>(mat)].data();
    const auto key = std::make_pair(mat, p.volume[i]);
    auto it = interior.find(key);
    if (it == interior.end()) {
      abi::Family ff = full.family(p.volume[i], in.delta, params);
      set_moments(law, ff, moments);
      Interior v{trial_response(law, ff, 1.0, 1.0),
                 theta_out >= 0 ? trial_dilatation(law, ff, theta_out, outs) : 0.0,
                 directions ? full_axis_trials(law, ff, theta_out, outs) : AxisTrials{}};
      it = interior.emplace(key, v).first;
    }
    const Interior& F = it->second;
    abi::Family f = gather.gather(i, nullptr);
    set_moments(law, f, moments);
    if (directions) {
      double* sd = &out.dilatation[static_cast<std::size_t>(i * nc)];
      double* sf = &out.force[static_cast<std::size_t>(i * nc)];
      axis_factors(law, f, theta_out, F.axes, outs, sd, sf);
      full_axes[static_cast<std::size_t>(i)] = &F.axes;
      continue;
    }
    double sd = 1.0, sf = 1.0;
    if (!law.has_dilatation_sum) {
      sf = F.R.dilatation / trial_response(law, f, 1.0, 1.0).dilatation;  // paper 002's trial
    } else if (in.match == SurfaceMatch::Terms) {
      sd = F.theta / trial_dilatation(law, f, theta_out, outs);
      sf = F.R.deviatoric / trial_response(law, f, sd, 1.0).deviatoric;
    } else {
      // R = u A + v B with u = s_f, v = s_f s_d (A: s_d = 0; B: the part through the
      // dilatation sum): linear in (u, v), one 2x2 system for the two trials.
      const Affine T = affine_response(law, f);
      const double det = T.A.dilatation * T.B.deviatoric - T.A.deviatoric * T.B.dilatation;
      const double u = (F.R.dilatation * T.B.deviatoric - F.R.deviatoric * T.B.dilatation) / det;
      const double v = (T.A.dilatation * F.R.deviatoric - T.A.deviatoric * F.R.dilatation) / det;
      sf = u, sd = v / u;
    }
    check_factors(in, i, sd, sf);
    out.dilatation[static_cast<std::size_t>(i)] = sd;
    out.force[static_cast<std::size_t>(i)] = sf;
  }
  if (directions) {
    make_self_consistent(law, b, gather, full_axes, theta_out, out);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < nc; ++k)
        check_factors(in, i, out.dilatation[static_cast<std::size_t>(i * nc + k)],
                      out.force[static_cast<std::size_t>(i * nc + k)]);
  }
  return out;
}

void apply_surface_correction(Bonds& b, const SurfaceFactors& s, bool has_dilatation_sum) {
  if (has_dilatation_sum) b.surface_dilatation = bond_factors(b, s.dilatation, s.components);
  b.surface_force = bond_factors(b, s.force, s.components);
}

}  // namespace pd
