#!/usr/bin/env python3
"""Writes the malformed-input cases of tests/cli/test_malformed_inputs.cpp into this directory.

Each case is one edit of a small valid scene, the text on the line the message must name
(the line is counted here, never taken from pd) and the key path and message the docs
promise. The expectation is appended as trailing comments, so it shifts no line:
  # expect: rejected | warned
  # message: REGEX   ({file} stands for the scene's path)
Usage: tests/cli/malformed/make_cases.py   (rewrites every case; commit the result)
"""
import re, os, sys
base = """dimension: 2
domain:
  box: {min: [0, 0], max: [1, 1]}
  count: 6
horizon: {ratio: 3.0}
law: silling_plane_strain
influence: const
materials:
  - {E: 1, nu: 0.25}
boundary:
  - region: {side: bottom}
    fixed: [x, y]
  - region: {side: top}
    traction: [0, 0.01]
solver: {tolerance: 1.0e-10}
output: {vtu: true, csv: true}
"""
# name, from, to, marker (text on the expected line; None: first line of `to`), path, message regex, kind
cases = [
 # bad types
 ("type_count_text", "count: 6", "count: six", None, "domain.count", "expected a number"),
 ("type_count_fraction", "count: 6", "count: 6.5", None, "domain.count", "expected an integer"),
 ("type_E_list", "{E: 1, nu: 0.25}", "{E: [1], nu: 0.25}", None, r"materials\[0\]\.E", "expected a number"),
 ("type_law_map", "law: silling_plane_strain", "law: {name: silling_plane_strain}", None, "law", "expected a string"),
 ("type_box_scalar", "box: {min: [0, 0], max: [1, 1]}", "box: 1", None, "domain.box", "expected a map"),
 ("type_fixed_number", "fixed: [x, y]", "fixed: 3", None, r"boundary\[0\]\.fixed", "'3' is not a component"),
 ("type_bool_text", "vtu: true", "vtu: maybe", None, "output.vtu", "expected true or false"),
 ("type_dimension_text", "dimension: 2", "dimension: two", None, "dimension", "expected a number"),
 # non-finite and out-of-range numbers
 ("nan_E", "E: 1,", "E: .nan,", None, r"materials\[0\]\.E", "expected a finite number"),
 ("inf_traction", "traction: [0, 0.01]", "traction: [0, .inf]", None, r"boundary\[1\]\.traction\[1\]", "expected a finite number"),
 ("negative_count", "count: 6", "count: -6", None, "domain.count", ""),
 ("zero_count", "count: 6", "count: 0", None, "domain.count", ""),
 ("negative_E", "E: 1,", "E: -1,", None, r"materials\[0\]", "Young"),
 ("nu_half", "nu: 0.25", "nu: 0.5", None, r"materials\[0\]", ""),
 ("negative_ratio", "ratio: 3.0", "ratio: -3.0", None, "horizon", ""),
 ("dimension_four", "dimension: 2", "dimension: 4", None, "dimension", ""),
 ("inverted_box", "box: {min: [0, 0], max: [1, 1]}", "box: {min: [1, 1], max: [0, 0]}", None, "domain.box", ""),
 ("negative_tolerance", "tolerance: 1.0e-10", "tolerance: -1.0e-10", None, "solver.tolerance", ""),
 # missing keys
 ("missing_law", "law: silling_plane_strain\n", "", "dimension: 2", r"\(top level\)", "missing required key 'law'"),
 ("missing_domain", "domain:\n  box: {min: [0, 0], max: [1, 1]}\n  count: 6\n", "", "dimension: 2", r"\(top level\)", "missing required key 'domain'"),
 ("missing_materials", "materials:\n  - {E: 1, nu: 0.25}\n", "", "dimension: 2", r"\(top level\)", "missing required key 'materials'"),
 ("missing_nu", "{E: 1, nu: 0.25}", "{E: 1}", None, r"materials\[0\]", ""),
 ("within_inverted", "region: {side: top}", "region: {side: top, within: {min: [1, 1], max: [0, 0]}}", None, r"boundary\[1\]\.region\.within", "max must not be below min"),
 ("missing_box_max", "region: {side: top}", "region: {box: {min: [0, 0.9]}}", None, r"boundary\[1\]\.region\.box", "missing required key 'max'"),
 # unknown keys and names
 ("unknown_top_key", "influence: const", "influence: const\ninfluense: cubic", "influense: cubic", "influense", "unknown key 'influense'"),
 ("unknown_material_key", "{E: 1, nu: 0.25}", "{E: 1, nu: 0.25, stab: 1}", None, r"materials\[0\]\.stab", "unknown key 'stab'"),
 ("unknown_law", "law: silling_plane_strain", "law: silling_plain_strain", None, "law", ""),
 ("unknown_influence", "influence: const", "influence: gaussian_blur", None, "influence", ""),
 ("unknown_side", "region: {side: top}", "region: {side: up}", None, r"boundary\[1\]\.region\.side", "'up' is not one of"),
 ("unknown_component", "fixed: [x, y]", "fixed: [x, w]", None, r"boundary\[0\]\.fixed", ""),
 # duplicate keys
 ("duplicate_law", "influence: const", "influence: const\nlaw: lps_plane_strain", "law: lps_plane_strain", "law", "duplicate key 'law' \\(first given on line 6"),
 ("duplicate_E", "{E: 1, nu: 0.25}", "{E: 1, nu: 0.25, E: 2}", None, r"materials\[0\]\.E", "duplicate key 'E'"),
 # bad lists
 ("list_materials_empty", "materials:\n  - {E: 1, nu: 0.25}", "materials: []", None, "materials", "give at least one material"),
 ("list_materials_map", "materials:\n  - {E: 1, nu: 0.25}", "materials: {E: 1, nu: 0.25}", None, "materials", "expected a list"),
 ("list_box_short", "max: [1, 1]", "max: [1]", None, r"domain\.box\.max", ""),
 ("list_traction_long", "traction: [0, 0.01]", "traction: [0, 0.01, 0, 4]", None, r"boundary\[1\]\.traction", ""),
 ("list_boundary_map", "boundary:\n  - region: {side: bottom}\n    fixed: [x, y]\n  - region: {side: top}\n    traction: [0, 0.01]",
  "boundary: {region: {side: bottom}, fixed: [x, y]}", None, "boundary", "expected a list"),
 ("list_segment_one_point", "output:", "cracks:\n  - segment: [[0.2, 0.5]]\noutput:", "  - segment", r"cracks\[0\]\.segment", "a 2D crack is a segment"),
 # body_force from a field (effects/body_force_field.cpp): the field must exist and have a body force
 ("body_force_unknown_field", "solver:", "body_force: {field: {solution: u3}}\nsolver:", "body_force:", r"body_force\.field\.solution", "'u3' is not one of"),
 ("body_force_field_without_density", "solver:", "body_force: {field: {solution: shear, traction: 1}}\nsolver:", "body_force:",
  r"body_force\.field\.solution", "'shear' has no body force density"),
 ("body_force_unknown_key", "solver:", "body_force: {field: {solution: u2}, scale: 2}\nsolver:", "body_force:", r"body_force\.scale", "unknown key 'scale'"),
 # YAML itself
 ("yaml_syntax_map_value", "  count: 6", "  count: 6: 7", None, "", "YAML syntax error"),
 ("yaml_syntax_tab_indent", "  count: 6", "\tcount: 6", None, "", "YAML syntax error"),
 ("yaml_top_level_list", None, "- dimension: 2\n- law: x\n", "- dimension: 2", r"\(top level\)", "expected a map"),
 ("yaml_empty_file", None, "", None, r"\(top level\)", "expected a map"),
 # setup-time checks that used to mislead ("increase the horizon ratio")
 ("overflowing_modulus", "E: 1,", "E: 1e308,", None, r"materials\[0\]\.E", r"1e\+308 is too large a modulus for double precision"),
 ("overflowing_modulus_1e200", "E: 1,", "E: 1e200,", None, r"materials\[0\]\.E", r"1e\+200 is too large a modulus for double precision"),
 # set-up checks on what the scene asks for: bad input (exit 2), not a failed solve
 ("no_stiffness", "ratio: 3.0", "ratio: 1.2", None, None, r"36 of 36 families give law silling_plane_strain no stiffness against some homogeneous strain"),
 ("missing_boundary", "boundary:\n  - region: {side: bottom}\n    fixed: [x, y]\n  - region: {side: top}\n    traction: [0, 0.01]\n", "", "dimension: 2", None,
  r"boundary: the scene has no boundary section, so nothing holds the body \(the body is under-constrained: no particle has its x displacement prescribed"),
 ("under_constrained", "fixed: [x, y]", "fixed: [y]", None, None, r"boundary: the body is under-constrained: no particle has its x displacement prescribed \(rigid translation in x\)"),
 ("disconnected_cluster", "output:", "cracks:\n  - segment: [[-1, 0.5], [2, 0.5]]\noutput:", "  - segment", None,
  r"boundary: a cluster of 18 particle\(s\) joined by intact bonds .* is disconnected from the rest of the body and under-constrained"),
 ("memory_count_99999", "count: 6", "count: 99999", None, None,
  r"domain: the scene needs at least [0-9.e+]+ GiB of memory for its particles and bonds alone \(1e\+10 particles.*this machine has [0-9.e+]+ GiB available"),
 ("horizon_beyond_the_body", "ratio: 3.0", "length: 5", None, None, "the horizon delta = 5 exceeds the body"),
 # two conditions prescribing different values on one component of a particle (the top-right corner)
 ("conflicting_displacements", "traction: [0, 0.01]", "displacement: {y: 0.01}\n  - region: {side: right, within: {min: [0.5, 0.5], max: [1, 1]}}\n    displacement: {y: 0.02}",
  "region: {side: right", r"boundary\[2\]",
  r"prescribes the y displacement 0\.02 on particle \d+ at \([0-9.]+, [0-9.]+\), which .*:13: boundary\[1\] already prescribes as the "
  r"displacement 0\.01: two conditions may constrain the same component only with the same value"),
 ("conflicting_fixed_and_displacement", "region: {side: top}\n    traction: [0, 0.01]", "region: {side: left}\n    displacement: {x: 0.01}",
  "region: {side: left}", r"boundary\[1\]",
  r"prescribes the x displacement 0\.01 on particle \d+ at \([0-9.]+, [0-9.]+\), which .*:11: boundary\[0\] already prescribes as the "
  r"fixed displacement 0:"),
]
warn_cases = [
 ("warn_crack_outside", "output:", "cracks:\n  - segment: [[3, 3], [4, 3]]\noutput:", "  - segment", r"cracks\[0\]", "the crack crosses no bond"),
 ("warn_traction_on_fixed_particles", "region: {side: top}", "region: {side: bottom}", "region: {side: bottom}\n    traction", r"boundary\[1\]",
  "the traction acts only on components whose displacement is prescribed: the constraints take it and it does no work"),
 ("warn_influence_ignored", "law: silling_plane_strain\ninfluence: const", "law: bond_based_constant_2d\ninfluence: cubic",
  "influence: cubic", "influence", "law bond_based_constant_2d does not read the influence function"),
 ("warn_unused_parameter", "{E: 1, nu: 0.25}", "{E: 1, nu: 0.25, parameters: {stabb: 1}}", None, r"materials\[0\]\.parameters\.stabb",
  "law silling_plane_strain takes no parameter 'stabb'"),
]
def make(name, frm, to, marker, path, msg, kind):
    if frm is None: text = to
    else:
        assert frm in base, (name, frm); text = base.replace(frm, to, 1)
    mk = marker if marker is not None else (to.split("\n")[0] if to else None)
    if mk is not None and text:
        pos = text.find(mk); assert pos >= 0, (name, mk); line = text[:pos].count("\n") + 1
    else: line = 1
    if path is None: loc = r"{file}: "
    elif path == "": loc = r"{file}:%d: " % line
    else: loc = r"{file}:%d: %s: " % (line, path)
    # The expectation goes last, as comments, so that it shifts no line of the scene.
    tail = "# expect: %s\n# message: %s%s\n" % (kind, loc, msg)
    open(os.path.join(sys.argv[1], name + ".yaml"), "w").write(text + ("" if text.endswith("\n") or not text else "\n") + tail)
if __name__ == "__main__":
    if len(sys.argv) < 2: sys.argv.append(os.path.dirname(os.path.abspath(__file__)))
make("valid_base", "dimension: 2", "dimension: 2", None, None, "", "accepted")  # the runner's control
# two conditions agreeing on the components they share (the top-right corner's y): accepted
make("agreeing_displacements", "traction: [0, 0.01]", "displacement: {y: 0.01}\n  - region: {side: right, within: {min: [0.5, 0.5], max: [1, 1]}}\n    displacement: {y: 0.01}",
     None, None, "", "accepted")
for c in cases: make(*c, "rejected")
for c in warn_cases: make(*c, "warned")
