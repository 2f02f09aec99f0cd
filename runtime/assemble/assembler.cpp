// Family-by-family assembly with the generated kernels.
#include "assemble/assembler.hpp"

#include <cmath>
#include <stdexcept>

#include "local_matrix.hpp"

namespace pd {

// Per-thread gathered family inputs; reused across families without allocation.
struct Assembler::Gather {
  std::vector<double> Y, V, dy, out, M;
  TangentScratch scratch;
  abi::Family family(const Assembler& a, int p, const std::vector<double>& u) {
    const int d = a.particles_.dim, b0 = a.bonds_.offsets[p], L = a.bonds_.family_size(p);
    Y.resize(static_cast<std::size_t>(L * d));
    V.resize(static_cast<std::size_t>(L));
    for (int k = 0; k < L; ++k) {
      const int q = a.bonds_.neighbor[b0 + k];
      V[k] = a.particles_.volume[q];
      for (int c = 0; c < d; ++c) Y[k * d + c] = a.bonds_.xi[(b0 + k) * d + c] + u[q * d + c] - u[p * d + c];
    }
    abi::Family f;
    f.n_bonds = L;
    f.xi = a.bonds_.xi.data() + static_cast<std::ptrdiff_t>(b0) * d;
    f.Y = Y.data();
    f.w = a.bonds_.w.data() + b0;
    f.alpha = a.bonds_.alpha.data() + b0;
    f.V = V.data();
    f.V0 = a.particles_.volume[p];
    f.delta = a.bonds_.delta[p];
    f.params = a.params_[static_cast<std::size_t>(a.particles_.material[p])].data();
    f.moments = a.moments_.data() + static_cast<std::ptrdiff_t>(p) * a.law_.n_moments;
    return f;
  }
};

Assembler::Assembler(const Particles& particles, const Bonds& bonds, const abi::LawDescriptor& law,
                     std::vector<std::vector<double>> params, bool intact)
    : particles_(particles),
      bonds_(bonds),
      law_(law),
      variant_(intact ? law.intact : law.damaged),
      params_(std::move(params)),
      intact_(intact),
      sparsity_(bonds, particles.dim) {
  for (const auto& p : params_)
    if (static_cast<int>(p.size()) != law.n_params) throw std::invalid_argument("assembler: wrong parameter count");
  update_moments();
}

void Assembler::update_moments() {
  const int n = particles_.size(), nm = law_.n_moments;
  moments_.assign(static_cast<std::size_t>(n) * nm + 1, 0.0);
  const std::vector<double> zero(static_cast<std::size_t>(n) * particles_.dim, 0.0);
#pragma omp parallel
  {
    Gather g;
    std::vector<double> m(static_cast<std::size_t>(nm) + 1);
#pragma omp for schedule(dynamic, 256)
    for (int p = 0; p < n; ++p) {
      const abi::Family f = g.family(*this, p, zero);
      variant_.moments(f, m.data());
      for (int i = 0; i < nm; ++i) moments_[static_cast<std::size_t>(p) * nm + i] = m[i];
    }
  }
  check_finite(moments_, "moments (weighted volume, shape tensor: a particle without intact bonds?)");
}

void Assembler::forces(const std::vector<double>& u, std::vector<double>& f) const {
  const int n = particles_.size(), d = particles_.dim;
  f.assign(static_cast<std::size_t>(n) * d, 0.0);
#pragma omp parallel
  {
    Gather g;
#pragma omp for schedule(dynamic, 256)
    for (int p = 0; p < n; ++p) {
      const abi::Family fam = g.family(*this, p, u);
      g.out.resize(static_cast<std::size_t>((fam.n_bonds + 1) * d));
      variant_.residual(fam, g.out.data());
      const int b0 = bonds_.offsets[p];
      for (int a = 0; a <= fam.n_bonds; ++a) {
        const int q = a == 0 ? p : bonds_.neighbor[b0 + a - 1];
        for (int c = 0; c < d; ++c) {
#pragma omp atomic
          f[static_cast<std::size_t>(q) * d + c] += g.out[a * d + c];
        }
      }
    }
  }
}

void Assembler::stiffness(const std::vector<double>& u, SparseMatrix& K, std::vector<double>* f) const {
  const int n = particles_.size(), d = particles_.dim, S = law_.n_states;
  if (K.nonZeros() != sparsity_.nonzeros()) K = sparsity_.zero_matrix();
  double* values = K.valuePtr();
  std::fill(values, values + K.nonZeros(), 0.0);
  if (f) f->assign(static_cast<std::size_t>(n) * d, 0.0);
#pragma omp parallel
  {
    Gather g;
#pragma omp for schedule(dynamic, 64)
    for (int p = 0; p < n; ++p) {
      const abi::Family fam = g.family(*this, p, u);
      const int L = fam.n_bonds, m = (L + 1) * d;
      g.out.resize(static_cast<std::size_t>(m));
      g.M.resize(static_cast<std::size_t>(m) * m);
      const abi::TangentFactors fac = g.scratch.view(d, S, L);
      variant_.tangent(fam, f ? g.out.data() : nullptr, fac);
      form_local_matrix(d, S, fam, fac, g.M.data());
      const int b0 = bonds_.offsets[p];
      for (int a = 0; a <= L; ++a) {
        const int qa = a == 0 ? p : bonds_.neighbor[b0 + a - 1];
        if (f)
          for (int c = 0; c < d; ++c) {
#pragma omp atomic
            (*f)[static_cast<std::size_t>(qa) * d + c] += g.out[a * d + c];
          }
        for (int b = 0; b <= L; ++b) {
          const int qb = b == 0 ? p : bonds_.neighbor[b0 + b - 1];
          for (int q = 0; q < d; ++q) {
            const int base = sparsity_.slot(qa, qb, 0, q);
            for (int r = 0; r < d; ++r) {
              // K = -df/du: the solver's sign.
#pragma omp atomic
              values[base + r] -= g.M[static_cast<std::size_t>(a * d + r) * m + b * d + q];
            }
          }
        }
      }
    }
  }
  check_finite(std::vector<double>(values, values + K.nonZeros()), "stiffness assembly");
}

void Assembler::apply_stiffness(const std::vector<double>& u, const std::vector<double>& v, std::vector<double>& out) const {
  const int n = particles_.size(), d = particles_.dim;
  out.assign(static_cast<std::size_t>(n) * d, 0.0);
#pragma omp parallel
  {
    Gather g;
#pragma omp for schedule(dynamic, 256)
    for (int p = 0; p < n; ++p) {
      const abi::Family fam = g.family(*this, p, u);
      const int L = fam.n_bonds, b0 = bonds_.offsets[p];
      g.dy.resize(static_cast<std::size_t>((L + 1) * d));
      g.out.resize(g.dy.size());
      for (int a = 0; a <= L; ++a) {
        const int q = a == 0 ? p : bonds_.neighbor[b0 + a - 1];
        for (int c = 0; c < d; ++c) g.dy[a * d + c] = v[static_cast<std::size_t>(q) * d + c];
      }
      variant_.jvp(fam, g.dy.data(), g.out.data());
      for (int a = 0; a <= L; ++a) {
        const int q = a == 0 ? p : bonds_.neighbor[b0 + a - 1];
        for (int c = 0; c < d; ++c) {
#pragma omp atomic
          out[static_cast<std::size_t>(q) * d + c] -= g.out[a * d + c];
        }
      }
    }
  }
}

std::vector<double> Assembler::particle_outputs(const std::vector<double>& u) const {
  const int n = particles_.size(), no = law_.n_outputs;
  std::vector<double> out(static_cast<std::size_t>(n) * no, 0.0);
  if (no == 0 || variant_.outputs == nullptr) return out;
#pragma omp parallel
  {
    Gather g;
#pragma omp for schedule(dynamic, 256)
    for (int p = 0; p < n; ++p) variant_.outputs(g.family(*this, p, u), out.data() + static_cast<std::ptrdiff_t>(p) * no);
  }
  return out;
}

void Assembler::check_finite(const std::vector<double>& values, const std::string& stage) const {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw std::runtime_error("non-finite value (" + std::to_string(values[i]) + ") in " + stage + ", law " + law_.name +
                               ", entry " + std::to_string(i));
}

}  // namespace pd
