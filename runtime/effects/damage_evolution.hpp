// Critical-stretch damage evolution as an Effect with after_step (damage_evolution.cpp).
#pragma once

#include <memory>

#include "assembly/force_operator.hpp"
#include "damage/critical_stretch.hpp"
#include "effects/effect.hpp"
#include "input/scene.hpp"
#include "kernel_abi.hpp"
#include "particles.hpp"

namespace pd {

struct DamageEffect {
  std::unique_ptr<Effect> effect;               // null without a `damage` section
  const CriticalStretchDamage* rule = nullptr;  // its s0 and tension rule (owned by effect)
};

// What the damage rule reads of the body: its particles, its law with the first material's
// parameters (s0 from G0) and the influence function.
struct DamageBody {
  const Particles& particles;
  const abi::LawDescriptor& law;
  const std::vector<double>& params;
  const abi::InfluenceDescriptor& influence;
};

// The scene's `damage` on `bonds` (read by `assembler`); `short_bonds` and
// `short_assembler` (optional): the static matrix-free preconditioner's, broken alike.
DamageEffect make_damage_evolution(const Scene& scene, const DamageBody& body, Bonds& bonds,
                                   ForceOperator& assembler, Bonds* short_bonds = nullptr,
                                   ForceOperator* short_assembler = nullptr);

}  // namespace pd
