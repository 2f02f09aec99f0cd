// The scene's cross-section rules, in one table (scene_rules.hpp).
#include "input/scene_rules.hpp"

#include <stdexcept>

#include "material/law_history.hpp"

namespace pd {

namespace {

using Findings = std::vector<Finding>;

Findings one(const YamlAt& at, const std::string& message) { return {{at.location(), message}}; }

// A parameter the law does not take is most likely a misspelt one (`stabb` for `stab`):
// the law then ran with its default, or refused, so say which names it takes.
Findings unused_law_parameters(const SceneReading& r) {
  Findings out;
  const abi::LawDescriptor& law = *r.law;
  std::string taken;
  for (int i = 0; i < law.n_params; ++i) taken += (i ? ", " : "") + std::string(law.param_names[i]);
  const YamlAt mats = r.section("materials");
  for (std::size_t i = 0; i < r.s.materials.size(); ++i) {
    const YamlAt material = mats.element(mats.node[i], i);
    for (const std::string& name : unused_parameters(law, r.s.materials[i].parameters)) {
      const YamlAt at = material.child(material.node["parameters"], "parameters")
                            .child(material.node["parameters"][name], name);
      out.push_back({at.location(), "law " + std::string(law.name) + " takes no parameter '" + name +
                                        "', it is ignored (the law's parameters: " +
                                        (taken.empty() ? "none" : taken) + ")"});
    }
  }
  return out;
}

// Every parameter the law takes has a value (given, or derived from the elastic constants)
// inside the range the law declares (a yield stress > 0): the first that does not is named
// at its key, or at the material when the value is derived.
Findings law_parameter_values(const SceneReading& r) {
  const YamlAt mats = r.section("materials");
  for (std::size_t i = 0; i < r.s.materials.size(); ++i) {
    const MaterialSpec& m = r.s.materials[i];
    const YamlAt material = mats.element(mats.node[i], i);
    std::vector<double> values;
    try {
      values = law_parameters(*r.law, m.elastic, m.plane, m.parameters);
    } catch (const std::invalid_argument& e) {
      return one(material, e.what());
    }
    for (int p = 0; p < r.law->n_params; ++p) {
      const std::string why = parameter_range_violation(*r.law, p, values[static_cast<std::size_t>(p)]);
      if (why.empty()) continue;
      const std::string name = r.law->param_names[p];
      if (!m.parameters.count(name)) return one(material, why);
      return one(material.child(material.node["parameters"], "parameters")
                     .child(material.node["parameters"][name], name),
                 why);
    }
  }
  return {};
}

// A law with memory (abi::has_history) is evaluated from its committed
// history, which the model keeps and the serial drivers commit: the static one after every
// converged load step (on the PETSc backend too: every rank commits from the gathered u),
// explicit dynamics every time step, dynamic relaxation (one load step) once it has
// converged (Model::commit_history). The other paths do not carry it yet
// and would evaluate every step from the virgin body, silently wrong after the first: they
// are refused.
Findings history_refusals(const SceneReading& r) {
  if (!abi::has_history(*r.law)) return {};
  const std::string why = "law " + r.s.law + " carries history (" + describe_history(*r.law) + "), ";
  const YamlAt solver = r.section("solver");
  // Relaxation is one load step from the virgin body (run/relaxation_run.cpp commits its
  // answer once); it has no physical time for a rate-dependent law.
  if (r.s.dynamics && r.s.dynamics->method == DynamicsMethod::relaxation && r.law->uses_time_step)
    return one(r.section("dynamics"),
               why +
                   "and reads the time step, which dynamic relaxation (pseudo-time) does not give: solve "
                   "it statically with solver.duration, or with method: explicit");
  if (r.s.dynamics && r.s.solver.backend == Backend::petsc)
    return one(solver.child(solver.node["backend"], "backend"),
               why + "which the PETSc backend does not carry between time steps yet: use the serial backend");
  // A rate-dependent law (viscoelastic) reads the duration of each step; a static solve
  // without solver.duration has no physical time to give it, and a step of 0 would silently
  // freeze the law in its instantaneous response.
  if (r.law->uses_time_step && !r.s.dynamics && r.s.solver.duration == 0)
    return one(r.section("law"),
               why +
                   "and reads the time step, which a static solve without physical time does not give: "
                   "give the load path its time with solver.duration, or run it with dynamics (method: "
                   "explicit)");
  if (r.s.gauss_points > 0) {
    const YamlAt domain = r.section("domain");
    return one(domain.child(domain.node["gauss_points"], "gauss_points"),
               why + "kept per bond: the Gauss-point families have no bonds to keep it on");
  }
  return {};
}

// Static scenes (no dynamics section) and relaxation have no time: each boundary condition
// in turn (its time function, then a velocity), then each crack, with the message for each.
Findings time_dependence(const SceneReading& r, const std::string& time, const std::string& velocity,
                         const std::string& crack_time) {
  Findings out;
  for (const BoundaryCondition& bc : r.s.boundary) {
    if (bc.time) out.push_back({bc.time_where, time});
    if (bc.kind == BoundaryCondition::Kind::Velocity) out.push_back({bc.where, velocity});
  }
  for (const Crack& c : r.s.cracks)
    if (c.time) out.push_back({c.time_where, crack_time});
  return out;
}

bool relaxation(const Scene& s) { return s.dynamics && s.dynamics->method == DynamicsMethod::relaxation; }

const std::vector<SceneRule> kRules{
    {"the horizon is at least one spacing", Section::horizon, false,
     [](const SceneReading& r) {
       return r.s.delta() < r.s.h * 0.999
                  ? one(r.section("horizon"), "the horizon must be at least one spacing h")
                  : Findings{};
     }},
    {"compensation needs a law with an energy kernel", Section::law, false,
     [](const SceneReading& r) {
       return r.s.compensation && r.law->intact.energy == nullptr
                  ? one(r.section("domain"), "compensation: law " + r.s.law +
                                                 " has no energy kernel, and the compensation factor is a "
                                                 "ratio of energy densities "
                                                 "(paper 002 eq. 3.61)")
                  : Findings{};
     }},
    {"a law that ignores the influence function is given const", Section::influence, true,
     [](const SceneReading& r) {
       // The generator found no path from w to the force.
       return r.law->ignores_influence && r.s.influence != "const"
                  ? one(r.section("influence"),
                        "law " + r.s.law +
                            " does not read the influence function (its micromodulus or kernel "
                            "is built in): '" +
                            r.s.influence +
                            "' leaves its forces unchanged and only weights the family checks and the bonds "
                            "a "
                            "short-horizon preconditioner keeps")
                  : Findings{};
     }},
    {"every material gives the law its parameters, in their ranges", Section::materials, false,
     law_parameter_values},
    {"a material parameter is one the law takes", Section::materials, true, unused_law_parameters},
    {"the particle file's materials are the scene's", Section::materials, false,
     [](const SceneReading& r) {
       if (!r.cloud) return Findings{};
       std::vector<std::string> names;
       for (const MaterialSpec& m : r.s.materials) names.push_back(m.name);
       try {
         particle_materials(*r.cloud, names);
       } catch (const SceneError& e) {
         const YamlAt domain = r.section("domain");
         return one(domain.child(domain.node["particles"], "particles"), e.what());
       }
       return Findings{};
     }},
    {"an inclusion's material is the scene's", Section::materials, false,
     [](const SceneReading& r) {
       for (std::size_t i = 0; i < r.s.inclusions.size(); ++i)
         if (r.s.material_index(r.s.inclusions[i].material) < 0)
           return one(
               r.top.child(r.root["domain"]["inclusions"][i], "domain.inclusions[" + std::to_string(i) + "]"),
               "unknown material '" + r.s.inclusions[i].material + "'");
       return Findings{};
     }},
    {"the body force of u1 and u2 is plane strain", Section::body_force, false,
     [](const SceneReading& r) {
       return r.s.body_force && r.s.materials[0].plane == PlaneAssumption::Stress
                  ? one(r.section("body_force"),
                        "u1 and u2's body force is the plane-strain one; the body's material is plane stress")
                  : Findings{};
     }},
    {"backend petsc runs no Gauss points", Section::solver, false,
     [](const SceneReading& r) {
       // The distributed families run the bond kernels; the Gauss families' assembler is serial.
       const YamlAt solver = r.section("solver");
       return r.s.solver.backend == Backend::petsc && r.s.gauss_points > 0
                  ? one(solver.child(solver.node["backend"], "backend"),
                        "backend petsc does not integrate over Gauss points (domain.gauss_points): its ranks "
                        "run "
                        "the bond families only; use the serial backend")
                  : Findings{};
     }},
    {"a law with history runs where its history is committed", Section::dynamics, false,
     [](const SceneReading& r) { return history_refusals(r); }},
    {"solver.duration times a static path of a rate-dependent law", Section::dynamics, false,
     [](const SceneReading& r) {
       if (r.s.solver.duration == 0) return Findings{};
       const YamlAt solver = r.section("solver");
       const YamlAt at = solver.child(solver.node["duration"], "duration");
       if (r.s.dynamics)
         return one(at,
                    "duration is the physical time of a static load path; a dynamics section keeps its "
                    "own time (dynamics.dt and steps): remove solver.duration");
       if (!r.law->uses_time_step)
         return one(at, "law " + r.s.law +
                            " does not read the time step (it is rate-independent), so solver.duration would "
                            "change nothing: remove it");
       return Findings{};
     }},
    {"damage.max_resolves belongs to static runs", Section::damage, false,
     [](const SceneReading& r) {
       return r.s.dynamics && r.s.damage && !r.s.damage->max_resolves_where.empty()
                  ? Findings{{r.s.damage->max_resolves_where,
                              "max_resolves belongs to implicit (Newton) runs: a dynamic run checks bonds "
                              "every "
                              "step"}}
                  : Findings{};
     }},
    {"the J-integral is static", Section::damage, false,
     [](const SceneReading& r) {
       return r.s.dynamics && !r.s.output.j_integral.empty()
                  ? one(r.section("output"),
                        "j_integral post-processes the static solution; dynamic scenes do not support it")
                  : Findings{};
     }},
    {"the smoothing is static", Section::damage, false,
     [](const SceneReading& r) {
       return r.s.dynamics && !r.s.output.smoothing_influence.empty()
                  ? one(r.section("output"),
                        "smoothing post-processes the static solution; dynamic scenes do not support it yet")
                  : Findings{};
     }},
    {"time functions and velocities need dynamics", Section::damage, false,
     [](const SceneReading& r) {
       return r.s.dynamics
                  ? Findings{}
                  : time_dependence(r, "time functions need a dynamics section",
                                    "velocity conditions need a dynamics section",
                                    "time functions need a dynamics section (a static crack pressure "
                                    "follows the load factor)");
     }},
    {"relaxation has no time functions or velocities", Section::damage, false,
     [](const SceneReading& r) {
       return relaxation(r.s)
                  ? time_dependence(r, "relaxation solves the static problem: no time functions",
                                    "relaxation solves the static problem: no velocity conditions",
                                    "relaxation solves the static problem: no time functions")
                  : Findings{};
     }},
    {"relaxation starts at rest", Section::damage, false,
     [](const SceneReading& r) {
       Findings out;
       if (relaxation(r.s))
         for (const InitialCondition& ic : r.s.dynamics->initial)
           if (ic.velocity != Point{})
             out.push_back({ic.where, "relaxation starts at rest: give an initial displacement only"});
       return out;
     }},
};

}  // namespace

const std::vector<SceneRule>& scene_rules() { return kRules; }

void apply_scene_rules(Section section, SceneReading& r) {
  for (const SceneRule& rule : kRules) {
    if (rule.after != section) continue;
    for (const Finding& f : rule.check(r)) {
      if (!rule.warning) throw SceneError(f.where + ": " + f.message);
      r.s.warnings.push_back(f.where + ": " + f.message);
    }
  }
}

}  // namespace pd
