// Damage evolution as an effect: after every converged step (a static load step, a time
// step, a relaxation iteration) bonds over the critical stretch break
// (damage/critical_stretch.hpp) and the assemblers that read those bonds recompute their
// moments. The pattern keeps the broken bonds' slots as zeros, so no symbolic
// re-analysis is needed. A static matrix-free run also breaks the bonds of its
// short-horizon preconditioner (`short_bonds`), with the same rule and s0.
#include "effects/damage_evolution.hpp"

#include <fmt/core.h>

#include <optional>

namespace pd {

namespace {
class DamageEvolution final : public Effect {
 public:
  // suffix: what the log says after the rule (where s0 came from, when bonds break).
  DamageEvolution(const Particles& p, Bonds& bonds, ForceOperator& assembler, double s0, bool tension_only,
                  std::string suffix)
      : damage_(p, bonds, s0, tension_only), assembler_(assembler), suffix_(std::move(suffix)) {}
  void also_break(const Particles& p, Bonds& bonds, ForceOperator& assembler) {
    short_damage_.emplace(p, bonds, damage_.s0(), damage_.tension_only());
    short_assembler_ = &assembler;
  }
  const CriticalStretchDamage& damage() const { return damage_; }
  std::string name() const override { return "damage"; }
  std::string describe() const override { return damage_.describe() + suffix_; }
  // On a rank (scope: its own families) a bond shared with another rank breaks on both:
  // each holds the same bits of u at both ends after the ghost update and the rule is
  // symmetric bit for bit (damage/critical_stretch.cpp). The count is then of the bond
  // entries broken in the scope's families.
  long long after_step(const double* u, FamilyScope scope) override {
    const int broken =
        scope.every_family() ? damage_.break_bonds(u) : damage_.break_family_bonds(u, *scope.owned);
    if (broken == 0) return 0;
    assembler_.update_moments();
    if (short_damage_) {
      const int short_broken = scope.every_family() ? short_damage_->break_bonds(u)
                                                    : short_damage_->break_family_bonds(u, *scope.owned);
      if (short_broken > 0) short_assembler_->update_moments();
    }
    return broken;
  }

 private:
  CriticalStretchDamage damage_;
  ForceOperator& assembler_;
  std::optional<CriticalStretchDamage> short_damage_;
  ForceOperator* short_assembler_ = nullptr;
  std::string suffix_;
};
}  // namespace

DamageEffect make_damage_evolution(const Scene& s, const DamageBody& m, Bonds& bonds,
                                   ForceOperator& assembler, Bonds* short_bonds,
                                   ForceOperator* short_assembler) {
  if (!s.damage) return {};
  const double s0 =
      critical_stretch(*s.damage, s.materials[0], s.dim, s.delta(), m.law, m.params, m.influence.weight);
  std::string suffix = critical_stretch_origin(*s.damage, s.dim, m.law);
  if (!s.dynamics)
    suffix += fmt::format(", between load steps (at most {} re-solves per step)", s.damage->max_resolves);
  auto effect = std::make_unique<DamageEvolution>(m.particles, bonds, assembler, s0, s.damage->tension_only,
                                                  std::move(suffix));
  if (short_bonds && short_assembler) effect->also_break(m.particles, *short_bonds, *short_assembler);
  const CriticalStretchDamage* rule = &effect->damage();
  return {std::move(effect), rule};
}

}  // namespace pd
