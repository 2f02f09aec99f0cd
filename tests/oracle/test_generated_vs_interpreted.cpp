// The generated kernels against the generator's own interpreter (generator/eval): every
// registered law is built again from its DSL source here, and its expressions -- the horizon
// sums level by level, the force state per bond, the energy density, the outputs and the
// history updates -- are evaluated in plain double arithmetic on random families, with no
// lowering, CSE, hoisting or scheduling. The generated moments, residual, energy, outputs
// and update kernels must agree to rounding, and so must the JVP kernel, the dense
// tangent formed from the tangent kernel's factors and the parameter-sensitivity kernel,
// against the chain rule through the horizon sums written out here with pdgen::diff's
// derivatives. A bug in emit/ (a wrong common subexpression,
// a sum accumulated in the wrong loop, a dropped term) fails here even where a finite-
// difference check of the tangent is too loose to see it, since both sides of that check
// would share the wrong residual.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "kernel_abi.hpp"
#include "pdgen/diff.hpp"
#include "pdgen/dsl.hpp"
#include "pdgen/eval.hpp"
#include "verify/random_family.hpp"

namespace {
using Values = std::unordered_map<int, double>;

// The law's expressions evaluated on one family by the interpreter.
class Oracle {
 public:
  Oracle(const pdgen::Law& law, const pd::verify::TestFamily& f) : law_(law), f_(f) {
    family_ = center_values();
    int top = 0;
    for (const pdgen::SumDef& s : law_.sums()) top = std::max(top, s.level);
    for (int level = 0; level <= top; ++level)  // a sum's body reads only lower levels
      for (const pdgen::SumDef& s : law_.sums()) {
        if (s.level != level) continue;
        double total = 0;
        for (int k = 0; k < f_.bonds(); ++k) total += pdgen::evaluate(s.body, bond_values(k));
        family_[symbol(s.symbol)] = total;
      }
  }

  // The horizon sums that do not read the deformation (the moments kernel's), in order.
  std::vector<double> moments() const {
    std::vector<double> m;
    for (const pdgen::SumDef& s : law_.sums())
      if (!s.is_state) m.push_back(family_.at(symbol(s.symbol)));
    return m;
  }
  // f_0 = sum V0 V t, f_k+1 = -V0 V t (kernel_abi.hpp).
  std::vector<double> forces() const {
    const int d = f_.dim;
    std::vector<double> out(static_cast<std::size_t>(f_.dofs()), 0.0);
    for (int k = 0; k < f_.bonds(); ++k) {
      const Values v = bond_values(k);
      for (int c = 0; c < d; ++c) {
        const double t = f_.V0 * f_.V[k] * pdgen::evaluate(law_.force_state()[c], v);
        out[c] += t;
        out[(k + 1) * d + c] = -t;
      }
    }
    return out;
  }
  // The directional derivative of forces() along dy by the chain rule written out here: each
  // state sum's increment level by level (its body through Y and through the lower states),
  // then each bond's force state through its own Y and every state. The derivatives are
  // pdgen::diff's, evaluated by the interpreter: no kernel program, no emitted code.
  std::vector<double> jvp(const std::vector<double>& dy) const {
    const int d = f_.dim;
    const auto dY = [&](int k, int c) { return dy[(k + 1) * d + c] - dy[c]; };
    std::unordered_map<int, double> dS;  // by state symbol
    std::vector<const pdgen::SumDef*> states;
    int top = 0;
    for (const pdgen::SumDef& s : law_.sums())
      if (s.is_state) states.push_back(&s), top = std::max(top, s.level);
    // Bond k's derivative of e along dy, through Y_k and the states already incremented.
    const auto along = [&](const pdgen::Expr& e, int k, const Values& v) {
      double total = 0;
      for (int c = 0; c < d; ++c) total += pdgen::evaluate(pdgen::diff(e, law_.Y()[c]), v) * dY(k, c);
      for (const auto& [state, increment] : dS)
        for (const pdgen::SumDef* s : states)
          if (symbol(s->symbol) == state) total += pdgen::evaluate(pdgen::diff(e, s->symbol), v) * increment;
      return total;
    };
    for (int level = 0; level <= top; ++level) {
      std::unordered_map<int, double> increments;
      for (const pdgen::SumDef* s : states) {
        if (s->level != level) continue;
        double total = 0;
        for (int k = 0; k < f_.bonds(); ++k) total += along(s->body, k, bond_values(k));
        increments[symbol(s->symbol)] = total;
      }
      dS.insert(increments.begin(), increments.end());
    }
    std::vector<double> out(static_cast<std::size_t>(f_.dofs()), 0.0);
    for (int k = 0; k < f_.bonds(); ++k) {
      const Values v = bond_values(k);
      for (int c = 0; c < d; ++c) {
        const double dt = f_.V0 * f_.V[k] * along(law_.force_state()[c], k, v);
        out[c] += dt;
        out[(k + 1) * d + c] = -dt;
      }
    }
    return out;
  }
  // d forces() / d parameter `p`, the whole family's value moved together (kernel_abi.hpp
  // SensitivityKernel), by forward mode written out here: each sum's derivative level by
  // level, moments before states (their bodies through p, its pair mean and the sums already
  // differentiated), then each bond's force state. pdgen::diff's derivatives, interpreted.
  std::vector<double> sensitivity(int p) const {
    const int d = f_.dim;
    std::vector<std::pair<pdgen::Expr, double>> moving{{law_.params()[static_cast<std::size_t>(p)], 1.0}};
    for (const pdgen::PairParamDef& q : law_.pair_params())
      if (q.param == p) moving.push_back({q.symbol, 1.0});
    const auto along = [&](const pdgen::Expr& e, const Values& v) {
      double total = 0;
      for (const auto& [sym, rate] : moving) total += pdgen::evaluate(pdgen::diff(e, sym), v) * rate;
      return total;
    };
    int top = 0;
    for (const pdgen::SumDef& s : law_.sums()) top = std::max(top, s.level);
    for (bool states : {false, true})
      for (int level = 0; level <= top; ++level) {
        std::vector<std::pair<pdgen::Expr, double>> done;
        for (const pdgen::SumDef& s : law_.sums()) {
          if (s.is_state != states || s.level != level) continue;
          double total = 0;
          for (int k = 0; k < f_.bonds(); ++k) total += along(s.body, bond_values(k));
          done.push_back({s.symbol, total});
        }
        moving.insert(moving.end(), done.begin(), done.end());
      }
    std::vector<double> out(static_cast<std::size_t>(f_.dofs()), 0.0);
    for (int k = 0; k < f_.bonds(); ++k) {
      const Values v = bond_values(k);
      for (int c = 0; c < d; ++c) {
        const double dt = f_.V0 * f_.V[k] * along(law_.force_state()[c], v);
        out[c] += dt;
        out[(k + 1) * d + c] = -dt;
      }
    }
    return out;
  }
  double energy() const { return pdgen::evaluate(law_.energy_density(), family_); }
  std::vector<double> outputs() const {
    std::vector<double> out;
    for (const pdgen::OutputDef& o : law_.outputs()) out.push_back(pdgen::evaluate(o.value, family_));
    return out;
  }
  // The history at the end of the step: bond-major per bond, and the center's.
  std::vector<double> bond_history() const {
    std::vector<double> out;
    for (int k = 0; k < f_.bonds(); ++k) {
      const Values v = bond_values(k);
      for (const pdgen::HistoryDef& h : law_.history()) out.push_back(pdgen::evaluate(h.updated, v));
    }
    return out;
  }
  std::vector<double> particle_history() const {
    std::vector<double> out;
    for (const pdgen::HistoryDef& h : law_.particle_history())
      out.push_back(pdgen::evaluate(h.updated, family_));
    return out;
  }

 private:
  static int symbol(const pdgen::Expr& e) { return pdgen::symbol_index(e); }

  // What the whole family shares: V0, delta, the time step, parameters, the center's history.
  Values center_values() const {
    Values v;
    v[symbol(law_.V0())] = f_.V0;
    v[symbol(law_.delta())] = f_.delta;
    v[symbol(law_.time_step_symbol())] = f_.time_step;
    for (std::size_t p = 0; p < law_.params().size(); ++p) v[symbol(law_.params()[p])] = f_.params[p];
    for (std::size_t i = 0; i < law_.particle_history().size(); ++i)
      v[symbol(law_.particle_history()[i].committed)] = f_.particle_history[i];
    return v;
  }
  // ... and bond k's own inputs (a family without surface correction: both factors 1).
  Values bond_values(int k) const {
    Values v = family_;
    const int d = f_.dim;
    for (int c = 0; c < d; ++c) {
      v[symbol(law_.xi()[c])] = f_.xi[k * d + c];
      v[symbol(law_.Y()[c])] = f_.Y[k * d + c];
    }
    v[symbol(law_.w())] = f_.w[k];
    v[symbol(law_.alpha())] = f_.alpha[k];
    v[symbol(law_.V())] = f_.V[k];
    v[symbol(law_.dilatation_factor())] = 1.0;
    v[symbol(law_.force_factor())] = 1.0;
    const std::size_t np = law_.params().size();
    for (const pdgen::PairParamDef& q : law_.pair_params()) {
      const double a = f_.params[static_cast<std::size_t>(q.param)];
      const double b = f_.nbr_params.empty() ? a : f_.nbr_params[k * np + static_cast<std::size_t>(q.param)];
      v[symbol(q.symbol)] =
          q.mean == pdgen::PairMean::harmonic ? pd::abi::harmonic_mean(a, b) : pd::abi::arithmetic_mean(a, b);
    }
    const std::size_t nh = law_.history().size();
    for (std::size_t i = 0; i < nh; ++i)
      v[symbol(law_.history()[i].committed)] = f_.history[static_cast<std::size_t>(k) * nh + i];
    return v;
  }

  const pdgen::Law& law_;
  const pd::verify::TestFamily& f_;
  Values family_;
};

// Element by element to 1e-12 of the vector's largest entry (the two evaluations differ only
// in the order of their operations), or of `floor` when that is larger (a column that is zero
// up to rounding, as d forces / d G of a family at yield in perfect plasticity).
void expect_same(const std::vector<double>& generated, const std::vector<double>& interpreted,
                 const std::string& what, double floor = 0.0) {
  ASSERT_EQ(generated.size(), interpreted.size()) << what;
  double scale = floor;
  for (const double v : interpreted) scale = std::max(scale, std::fabs(v));
  for (std::size_t i = 0; i < generated.size(); ++i) {
    ASSERT_TRUE(std::isfinite(interpreted[i])) << what << " [" << i << "]";
    EXPECT_NEAR(generated[i], interpreted[i], 1e-12 * scale) << what << " [" << i << "]";
  }
}

struct Case {
  pd::verify::Truncation truncation;
  bool material_jump;
  unsigned seed;
};
}  // namespace

TEST(GeneratedVsInterpreted, EveryLawsKernelsEvaluateItsExpressions) {
  int laws = 0;
  for (const pdgen::LawEntry& entry : pdgen::law_registry()) {
    pdgen::law_under_construction().clear();
    const pdgen::Law law = entry.build();
    const pd::abi::LawDescriptor* descriptor = pd::abi::find_law(law.name());
    ASSERT_NE(descriptor, nullptr) << law.name() << " is registered but not in the generated law table";
    ++laws;
    const pdgen::Law intact = law.with_alpha_folded();
    const struct {
      const char* name;
      const pdgen::Law& law;
      const pd::abi::KernelVariant& kernels;
    } variants[] = {{"damaged", law, descriptor->damaged}, {"intact", intact, descriptor->intact}};
    const Case cases[] = {{pd::verify::Truncation::Interior, false, 3},
                          {pd::verify::Truncation::Corner, false, 4},
                          {pd::verify::Truncation::Edge, true, 5}};
    for (const auto& variant : variants)
      for (const Case& c : cases) {
        pd::verify::FamilyOptions o;
        o.dim = law.dim();
        o.truncation = c.truncation;
        o.broken_bonds = std::string(variant.name) == "damaged";
        o.material_jump = c.material_jump && !law.pair_params().empty();
        o.seed = c.seed;
        pd::verify::TestFamily f = pd::verify::make_family(*descriptor, o);
        f.use_declared_test_values();
        f.update_moments(variant.kernels);
        // A law with memory: one committed step first, so the history read is not the initial one.
        if (law.has_history()) {
          f.commit_update(variant.kernels);
          std::vector<double> y = f.y;
          for (std::size_t i = 0; i < y.size(); ++i)
            y[i] += 0.01 * std::sin(1.0 + 3.0 * static_cast<double>(i));
          f.set_positions(y);
        }
        const std::string where = law.name() + " " + variant.name + " seed " + std::to_string(c.seed);
        SCOPED_TRACE(where);
        const Oracle oracle(variant.law, f);
        const std::vector<double> moments = oracle.moments();
        ASSERT_EQ(static_cast<int>(moments.size()), descriptor->n_moments);
        expect_same(std::vector<double>(f.moments.begin(), f.moments.begin() + descriptor->n_moments),
                    moments, "moments");
        expect_same(f.forces(variant.kernels), oracle.forces(), "residual");
        // The tangent along a random dy: the JVP kernel, and the dense matrix the tangent
        // kernel's factors form (the law's own form kernel), times dy.
        std::vector<double> dy(static_cast<std::size_t>(f.dofs()));
        for (std::size_t i = 0; i < dy.size(); ++i) dy[i] = std::cos(0.7 + 2.3 * static_cast<double>(i));
        const std::vector<double> expected = oracle.jvp(dy);
        std::vector<double> df(dy.size());
        variant.kernels.jvp(f.view(), dy.data(), df.data());
        expect_same(df, expected, "jvp");
        const std::vector<double> M = f.tangent_matrix(variant.kernels);
        std::vector<double> Mdy(dy.size(), 0.0);
        for (std::size_t i = 0; i < dy.size(); ++i)
          for (std::size_t j = 0; j < dy.size(); ++j) Mdy[i] += M[i * dy.size() + j] * dy[j];
        expect_same(Mdy, expected, "tangent (formed) times dy");
        // The parameter sensitivities, where their contract holds (one material in the family).
        if (f.nbr_params.empty()) {
          const int n = f.dofs(), np = descriptor->n_params;
          std::vector<double> dfdp(static_cast<std::size_t>(n * np));
          variant.kernels.sensitivity(f.view(), dfdp.data());
          double force_scale = 0;
          for (const double v : oracle.forces()) force_scale = std::max(force_scale, std::fabs(v));
          for (int p = 0; p < np; ++p)
            expect_same(std::vector<double>(dfdp.begin() + p * n, dfdp.begin() + (p + 1) * n),
                        oracle.sensitivity(p), std::string("sensitivity to ") + descriptor->param_names[p],
                        force_scale / std::max(std::fabs(f.params[static_cast<std::size_t>(p)]), 1e-3));
        }
        if (law.has_energy()) {
          ASSERT_NE(variant.kernels.energy, nullptr);
          expect_same({variant.kernels.energy(f.view())}, {oracle.energy()}, "energy");
        }
        if (!law.outputs().empty()) {
          std::vector<double> out(law.outputs().size());
          variant.kernels.outputs(f.view(), out.data());
          expect_same(out, oracle.outputs(), "outputs");
        }
        if (law.has_history()) {
          expect_same(f.updated_history(variant.kernels), oracle.bond_history(), "bond history update");
          expect_same(f.updated_particle_history(variant.kernels), oracle.particle_history(),
                      "particle history update");
        }
      }
  }
  EXPECT_EQ(laws, static_cast<int>(pd::abi::all_laws().size()));  // every generated law was checked
}
