#!/usr/bin/env python3
"""Writes docs/performance.md from one run of the benchmark suite (Google Benchmark JSON).

usage: report.py --command CMD --kernels kernels.json --assembly a1.json [a2.json ...]
                 [--profile bench/profile.md] [--build build] [--seconds N]
Medians of the repetitions; every ratio compares medians measured in the same run.
"""
import argparse
import json
import os
import platform
import re
import statistics
import subprocess
from collections import defaultdict

UNIT = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
KERNEL_KINDS = ["generated_residual", "generated_tangent_factors", "generated_tangent_dense", "generic_form_tangent_dense",
                "generated_tangent_pair_blocks", "generated_jvp", "sacado_dfad_tangent_dense", "sacado_slfad_tangent_dense",
                "forward_ad_tangent_dense", "forward_ad_fixed_tangent_dense", "central_fd_tangent_dense"]
AD_KINDS = ["sacado_dfad_tangent_dense", "sacado_slfad_tangent_dense", "forward_ad_tangent_dense", "forward_ad_fixed_tangent_dense"]
# The published PeriFlakes kernels (paper 000), dense K and R per family call, CPU time, median, as issue 19
# quotes them for this machine kind: (law, bonds) -> (µs at -O2 -fno-math-errno, µs at -Ofast -march=native).
# Not measured by this suite (PeriFlakes is not part of the build): the goals compare with them.
PERIFLAKES_US = {("silling_plane_strain", 12): (1.62, 1.21), ("silling_plane_strain", 36): (11.8, 9.12),
                 ("correspondence_plane_strain", 12): (0.94, 0.51), ("correspondence_plane_strain", 36): (6.21, 2.50)}
LAWS = [("silling", "Silling dilatation law (`silling_plane_strain`, `silling_3d`)"),
        ("oterkus", "Oterkus dilatation law (`oterkus_plane_strain`; 2D only)"),
        ("correspondence", "Correspondence, no stabilisation (`correspondence_plane_strain`, `correspondence_3d`)"),
        ("bond_based", "Bond-based, constant micromodulus (`bond_based_constant_2d`, `bond_based_constant_3d`)"),
        ("elastic_plastic", "Mitchell's elastic-plastic law, a law with memory (`elastic_plastic_plane_strain`, "
         "`elastic_plastic_3d`): the incremental residual from a committed plastic extension, on the yielding branch")]


def load_runs(paths):
    """name -> list of per-repetition entries (iteration runs only); plus the first context."""
    runs, context = defaultdict(list), None
    for path in paths:
        data = json.load(open(path))
        context = context or data["context"]
        for b in data["benchmarks"]:
            if b.get("run_type") == "aggregate" or b.get("error_occurred"):
                continue
            runs[b.get("run_name", b["name"])].append(b)
    return runs, context


def median_ns(entries, clock="real_time"):
    return statistics.median(e[clock] * UNIT[e["time_unit"]] for e in entries)


def sh(cmd):
    try:
        return subprocess.run(cmd, capture_output=True, text=True, shell=True).stdout.strip()
    except OSError:
        return ""


def cmake_cache(build):
    cache = {}
    try:
        for line in open(os.path.join(build, "CMakeCache.txt")):
            m = re.match(r"([A-Za-z_0-9]+):[A-Z]+=(.*)$", line.strip())
            if m:
                cache[m.group(1)] = m.group(2)
    except OSError:
        pass
    return cache


def machine_lines(context, build, seconds, command):
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), platform.processor())
    mem = next((l.split()[1] for l in open("/proc/meminfo") if l.startswith("MemTotal")), "0")
    cache = cmake_cache(build)
    cxx = cache.get("CMAKE_CXX_COMPILER", "c++")
    version = sh("%s --version | head -1" % cxx)
    flags = " ".join(f for f in [cache.get("CMAKE_CXX_FLAGS", ""), cache.get("CMAKE_CXX_FLAGS_%s" % cache.get("CMAKE_BUILD_TYPE", "RELEASE").upper(), "")] if f)
    eigen = sh("grep -E '#define EIGEN_(WORLD|MAJOR|MINOR)_VERSION' /usr/include/eigen3/Eigen/src/Core/util/Macros.h | awk '{print $3}' | paste -sd.")
    gbench = sh("dpkg-query -W -f='${Version}' libbenchmark-dev")
    blas = sh("readlink -f /usr/lib/x86_64-linux-gnu/libblas.so.3")
    conf = dict(l.split(None, 1) for l in sh("getconf -a").splitlines() if len(l.split(None, 1)) == 2)
    caches = ["%s %d KiB" % (label, int(conf[key]) // 1024) for label, key in
              (("L1d", "LEVEL1_DCACHE_SIZE"), ("L2", "LEVEL2_CACHE_SIZE")) if conf.get(key, "0").strip().isdigit() and int(conf[key])]
    isa = next((l.split(":", 1)[1].split() for l in open("/proc/cpuinfo") if l.startswith("flags")), [])
    caches.append("ISA up to %s" % ("AVX-512" if "avx512f" in isa else "AVX2" if "avx2" in isa else "SSE4" if "sse4_2" in isa else "SSE2"))
    caches = ", ".join(caches) or "cache sizes n/a"
    load = context.get("load_avg", [])
    out = ["- Machine: %s, %d logical CPUs at %.0f MHz (%s), %.1f GiB RAM; %s" % (
        cpu, context.get("num_cpus", 0), context.get("mhz_per_cpu", 0), caches, int(mem) / 2**20, platform.platform()),
        "- Shared and noisy: load average %s when the run started; the kernels' repetitions are randomly interleaved "
        "(`--benchmark_enable_random_interleaving`), the assembly runs one grid per process." % (
            " / ".join("%.2f" % x for x in load) if load else "n/a"),
        "- Compiler: %s; flags `%s -std=c++20 -fopenmp` (CMake %s, no `-march`: SSE2 code)" % (
            version, flags, cache.get("CMAKE_BUILD_TYPE", "Release")),
        "- Eigen %s, Google Benchmark %s (Debian's libbenchmark prints \"Library was built as DEBUG\": that is its own "
        "timing loop, not the code measured); BLAS `%s`" % (eigen, gbench, blas),
        "- Kernel results dated %s; this `%s` took %s (stages run with --only keep the other stages' results in build/bench/)." % (context.get("date", ""), command, "%.0f s" % seconds if seconds else "n/a")]
    return out


def fmt_ns(t):
    if t != t:
        return "–"
    return "%.0f" % t if t < 1e5 else "%.3g" % t


def ratio(a, b):
    return a / b if a == a and b == b and b > 0 else float("nan")


def fmt_ratio(r):
    return "–" if r != r else ("%.1f×" % r if r < 100 else "%.0f×" % r)


def kernel_section(path):
    runs, _ = load_runs([path])
    table = defaultdict(dict)  # (law, ratio label) -> kind -> (median ns, entries)
    for name, entries in runs.items():
        m = re.match(r"([a-z_]+)/([a-z_0-9]+)/([0-9.a-z]+)$", name)
        if m and (m.group(1) in KERNEL_KINDS):
            # CPU time: the kernels run on one thread, and on this shared machine the wall
            # time also counts the time the process waited for a core (up to 3x, unevenly
            # across the interleaved benchmarks, which distorts the ratios).
            table[(m.group(2), m.group(3))][m.group(1)] = (median_ns(entries, "cpu_time"), entries)
    out = ["## Kernels: one family, five laws\n",
           "`build/bin/kernel_bench`. Families are perturbed lattice neighbourhoods (`lattice_family` in "
           "`bench/kernel_bench.cpp`): the lattice points within delta/h of the center (square lattice: 8, 12, 28, 36 and "
           "44 bonds at delta/h = 1.5, 2, 3, 3.5 and sqrt(13) = 3.61; cubic lattice: 122 at delta/h = 3), positions moved "
           "by up to 0.1 h, then a random 5% displacement gradient plus noise. Intact variants (alpha = 1). Times are "
           "medians in ns of one family, CPU time (single-threaded kernels; the wall time of a shared machine also counts waiting for a core):\n",
           "- *residual*: the generated nodal forces; *factors*: the generated tangent kernel (forces and the factors "
           "direct/left/right of the kernel ABI, O(L)); *dense*: factors formed into the (L+1)d × (L+1)d local matrix by "
           "the law's generated form kernel (`KernelVariant::form`: the law's structurally zero factor entries skipped; "
           "what the assembler scatters); *dense generic*: the same matrix by `form_local_matrix`'s generic forming; "
           "*pair blocks*: for laws without states, the L+1 d × d blocks that are all of their local matrix "
           "(`form_pair_blocks`); *JVP*: the generated tangent–vector product.",
           "- *AD*: forward-mode AD of a hand-written templated residual of the same law (`bench/reference_laws.hpp`) over "
           "all (L+1)d family dofs: Trilinos Sacado's `DFad<double>` (heap derivative array sized at run time, what "
           "Peridigm uses) and `SLFad<double, N>` (fixed capacity, no allocation), Eigen's `AutoDiffScalar` with a "
           "`VectorXd` derivative (heap) and with a fixed-capacity one (90 resp. 369 doubles). All reuse their AD "
           "workspace and seeded inputs between calls and evaluate each per-bond quantity once. *best AD* is the fastest "
           "of the four.",
           "- *FD*: central differences of the generated residual, one residual pair per dof (2(L+1)d calls), step "
           "1e-5 h, bond vectors perturbed in place (no allocation).",
           "- Before timing, each AD and FD benchmark checks its matrix against *dense*: max |difference| / max |entry| "
           "<= 1e-8 (FD on the elastic-plastic law's yielding branch: 1e-6, since the return map's curvature takes "
           "central differences' O(step^2) error above 1e-8 there), and the hand-written residual against the generated "
           "one to 1e-12; the benchmark exits with an error otherwise. Largest differences in this run: see the last "
           "column.",
           "- Ratios: AD / dense and FD / dense compare like with like (all produce the dense matrix); generic / dense is "
           "what the generated form kernel saves; factors / residual is the tangent kernel's cost over the residual's.\n"]
    goals, goals_3d = [], []
    for key, title in LAWS:
        rows = sorted(((k, v) for k, v in table.items() if k[0].startswith(key)),
                      key=lambda kv: (kv[0][0].endswith("3d"), kv[1]["generated_residual"][1][0].get("bonds", 0)))
        if not rows:
            continue
        out.append("### %s\n" % title)
        out.append("| law | delta/h | bonds | residual | factors | dense | dense generic | pair blocks | JVP | Sacado DFad | Sacado SLFad | Eigen AD heap | Eigen AD fixed | FD | DFad / dense | best AD / dense | FD / dense | generic / dense | factors / residual | max rel. diff AD, FD |")
        out.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for (law, label), row in rows:
            get = lambda k: row[k][0] if k in row else float("nan")
            bonds = int(row["generated_residual"][1][0].get("bonds", 0))
            dense, fac, res = get("generated_tangent_dense"), get("generated_tangent_factors"), get("generated_residual")
            ads = [get(k) for k in AD_KINDS if k in row]
            best_ad = min(ads) if ads else float("nan")
            fd = get("central_fd_tangent_dense")
            diffs = [max(max(e.get("rel_diff", 0) for e in row[k][1]) for k in kinds if k in row)
                     for kinds in (AD_KINDS, ["central_fd_tangent_dense"]) if any(k in row for k in kinds)]
            out.append("| %s | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                law, label.replace("sqrt13", "3.61"), bonds, fmt_ns(res), fmt_ns(fac), fmt_ns(dense),
                fmt_ns(get("generic_form_tangent_dense")), fmt_ns(get("generated_tangent_pair_blocks")),
                fmt_ns(get("generated_jvp")), fmt_ns(get("sacado_dfad_tangent_dense")), fmt_ns(get("sacado_slfad_tangent_dense")),
                fmt_ns(get("forward_ad_tangent_dense")), fmt_ns(get("forward_ad_fixed_tangent_dense")), fmt_ns(fd),
                fmt_ratio(ratio(get("sacado_dfad_tangent_dense"), dense)), fmt_ratio(ratio(best_ad, dense)),
                fmt_ratio(ratio(fd, dense)), fmt_ratio(ratio(get("generic_form_tangent_dense"), dense)),
                "%.2f" % ratio(fac, res), ", ".join("%.1e" % d for d in diffs)))
            if (law, bonds) in PERIFLAKES_US:
                goals.append((law, bonds, dense))
            if law == "silling_3d":
                goals_3d.append((law, label, dense, get("sacado_dfad_tangent_dense"), get("sacado_slfad_tangent_dense"), fac, res))
        out.append("")
    if goals:
        out.append("### Issue 19's kernel goals against the published PeriFlakes times\n")
        out.append("*dense* of this run (the generated form kernel, default flags) against the PeriFlakes times issue 19 quotes "
                   "(not measured here: PeriFlakes is not built by this suite). Goal: *dense* ≤ 1/10 of PeriFlakes at "
                   "`-O2 -fno-math-errno` and ≤ 1/3 at `-Ofast -march=native`.\n")
        out.append("| law | bonds | dense ns | PeriFlakes -O2 ns | ratio | goal ≥ 10× | PeriFlakes -Ofast native ns | ratio | goal ≥ 3× |")
        out.append("|---|---|---|---|---|---|---|---|---|")
        for law, bonds, dense in goals:
            o2, ofast = (1e3 * t for t in PERIFLAKES_US[(law, bonds)])
            r2, rf = ratio(o2, dense), ratio(ofast, dense)
            out.append("| %s | %d | %s | %.0f | %s | %s | %.0f | %s | %s |" % (
                law, bonds, fmt_ns(dense), o2, fmt_ratio(r2), "yes" if r2 >= 10 else "no", ofast, fmt_ratio(rf),
                "yes" if rf >= 3 else "no"))
        out.append("")
    for law, label, dense, dfad, slfad, fac, res in goals_3d:
        out.append("**3D Silling at delta/h = %s** (goal: dense ≥ 25× faster than a Sacado forward-AD Jacobian; factors ≤ 1.5× "
                   "the residual): Sacado DFad / dense %s, SLFad / dense %s; factors / residual %.2f.\n" % (
                       label, fmt_ratio(ratio(dfad, dense)), fmt_ratio(ratio(slfad, dense)), ratio(fac, res)))
    return out


def native_section(portable_path, native_path):
    """The same kernel benchmarks built portably (the release default) and with -march=native."""
    def medians(path):
        runs, _ = load_runs([path])
        return {name: median_ns(e, "cpu_time") for name, e in runs.items()}
    port, nat = medians(portable_path), medians(native_path)
    kinds = ["generated_residual", "generated_tangent_factors", "generated_tangent_dense", "generated_jvp",
             "sacado_dfad_tangent_dense", "forward_ad_fixed_tangent_dense", "central_fd_tangent_dense"]
    out = ["### Flags: portable (release default) against `-march=native`\n",
           "`build/bin/kernel_bench_native`: the generated kernels and the benchmark (AD references included) compiled "
           "with `-march=native` (this host: AVX-512), run right after `kernel_bench` with the same options. Median ns, "
           "CPU time; *×* = portable / native (above 1: native is faster).\n",
           "| law | delta/h | " + " | ".join(k.replace("generated_", "").replace("_tangent_dense", "").replace("_dense", "")
                                          for k in kinds) + " |",
           "|---|---|" + "---|" * len(kinds)]
    cases = sorted({tuple(n.split("/")[1:]) for n in port if n.startswith("generated_residual/")})
    for law, label in cases:
        cells = []
        for k in kinds:
            name = "%s/%s/%s" % (k, law, label)
            if name in port and name in nat:
                cells.append("%s / %s (%.2f×)" % (fmt_ns(port[name]), fmt_ns(nat[name]), port[name] / nat[name]))
            else:
                cells.append("–")
        out.append("| %s | %s | %s |" % (law, label.replace("sqrt13", "3.61"), " | ".join(cells)))
    out.append("")
    return out


def assembly_section(paths):
    runs, _ = load_runs(paths)
    rows = {}
    for name, entries in runs.items():
        m = re.match(r"([a-z_]+)/(\d+)/(\d+)/(\d+)", name)
        if not m:
            continue
        op, n, r, t = m.group(1), int(m.group(2)), int(m.group(3)), int(m.group(4))
        rows[(op, n, r, t)] = (median_ns(entries) / 1e6, entries[-1])
    order = ["forces", "stiffness_product", "stiffness", "sparse_product"]
    out = ["## Global assembly: `pd::FamilyAssembler`, Silling plane strain, n × n grid, cubic influence\n",
           "`build/bin/assembly_bench`, one grid per process. *forces*: internal nodal forces f(u); *stiffness_product*: "
           "matrix-free K(u) v from the generated JVP kernel; *stiffness*: K(u) = -df/du and f(u) together (a Newton "
           "step's assembly): tangent factors, `form_local_matrix`, scatter into the family's precomputed slots, colour by "
           "colour (OpenMP, no atomics); *sparse_product*: K v with the assembled matrix (Eigen, 1 thread), for "
           "comparison. families/s = particles / time; nonzeros/s = nonzeros of K / time. Median ms of the repetitions.\n",
           "| grid | delta/h | bonds/particle | operation | threads | ms | families/s | nonzeros/s | 2 threads vs 1 |",
           "|---|---|---|---|---|---|---|---|---|"]
    grids = sorted({(n, r) for (_, n, r, _) in rows})
    for n, r in grids:
        for op in order:
            for t in (1, 2):
                if (op, n, r, t) not in rows:
                    continue
                ms, e = rows[(op, n, r, t)]
                particles = e.get("particles", n * n)
                nnz = e.get("nonzeros_per_particle", 0) * particles
                speed = ""
                if t == 2 and (op, n, r, 1) in rows:
                    speed = "%.2f×" % (rows[(op, n, r, 1)][0] / ms)
                out.append("| %d² | %.1f | %.1f | %s | %d | %.3g | %.3g | %s | %s |" % (
                    n, r / 10, e.get("bonds_per_particle", 0), op, t, ms, particles / (ms / 1e3),
                    "%.3g" % (nnz / (ms / 1e3)) if nnz and op in ("stiffness", "sparse_product") else "", speed))
    out.append("")
    out.append("### Peak memory per particle\n")
    out.append("Peak resident set (VmHWM, reset through `/proc/self/clear_refs` before the grid is built) minus the "
               "resident set before it, divided by the particle count. *matrix-free*: particles, bonds, assembler "
               "(moments, colouring) and the vectors, while forces and K v run; *with K*: plus the two-horizon pattern, "
               "the per-family slot table ((L+1)² ints per family) and K (values and 32-bit row indices), while K is "
               "assembled. The 1000² grid at delta/h = 3.5 is run matrix-free only (see the projection).\n")
    out.append("| grid | delta/h | bonds/particle | K nonzeros/particle | colours | matrix-free bytes/particle | with K bytes/particle |")
    out.append("|---|---|---|---|---|---|---|")
    per_ratio = {}
    for n, r in grids:
        mf = rows.get(("forces", n, r, 1)) or rows.get(("forces", n, r, 2))
        k = rows.get(("stiffness", n, r, 1)) or rows.get(("stiffness", n, r, 2))
        e = (k or mf)[1]
        out.append("| %d² | %.1f | %.1f | %s | %d | %s | %s |" % (
            n, r / 10, e.get("bonds_per_particle", 0), "%.0f" % k[1]["nonzeros_per_particle"] if k else "–",
            e.get("colours", 0), "%.0f" % mf[1]["peak_bytes_per_particle"] if mf and "peak_bytes_per_particle" in mf[1] else "–",
            "%.0f" % k[1]["peak_bytes_per_particle"] if k and "peak_bytes_per_particle" in k[1] else "–"))
        if k and "peak_bytes_per_particle" in k[1]:
            per_ratio[r] = (n, k[1]["peak_bytes_per_particle"], k[1]["nonzeros_per_particle"])
    out.append("")
    for r, (n, b, nnz) in sorted(per_ratio.items()):
        if not any(key == ("stiffness", 1000, r, 1) for key in rows) and any(key[1] == 1000 and key[2] == r for key in rows):
            out.append("Projection: at delta/h = %.1f the assembled path took %.0f bytes per particle on the %d² grid "
                       "(%.0f nonzeros per particle), so 1000² would need about %.1f GB with K — not run on this shared "
                       "machine; the matrix-free path is measured at 1000² above.\n" % (r / 10, b, n, nnz, b * 1e6 / 1e9))
    return out


def solve_section(paths):
    rows = []
    for path in paths:
        if os.path.exists(path):
            rows += [json.loads(line) for line in open(path) if line.strip()]
    if not rows:
        return []
    out = ["## Solves of the pressurised crack: each linear-solver path\n",
           "`bench/solve_bench.py` (called by bench/run.sh): scenes/crack.yaml (Silling plane strain, cubic influence, "
           "Westergaard field on the collar) on n × n grids, one `pd run` process per point. *cholmod*: the assembled "
           "tangent factorised; *cg+ic*: CG with incomplete Cholesky on the assembled tangent; *matrix-free*: Newton–Krylov "
           "on the generated tangent–vector product with the factorised δ/h = 2 stiffness (*short horizon*) or Jacobi as "
           "preconditioner, both with Eisenstat–Walker forcing; *auto*: what `pd run` picks by default (its choice in the "
           "last column). Peak = the process's maximum resident set (`wait4`). Krylov = iterations summed over the Newton "
           "steps. A point is not run when the same path's previous grid, scaled linearly in particles, projects past the "
           "time or memory limit. *load*: the 1-minute load average before → after the point; on this shared 2-core "
           "machine a point run beside other work took up to 7× longer than the same point alone, so compare rows of "
           "similar load.\n",
           "| grid | δ/h | path | method | nonzeros | Newton | Krylov | setup s | assembly s | linear s | total s | peak MB | "
           "kB/particle | field error | auto's choice | load |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        head = "| %d² | %g | %s |" % (r["grid"], r["ratio"], r["solver"])
        if "skipped" in r:
            out.append(head + " not run: %s ||||||||||||" % r["skipped"])
        elif "error" in r:
            out.append(head + " failed: %s ||||||||||||" % r["error"].replace("|", "/"))
        else:
            out.append(head + " %s | %.3g | %d | %d | %.3g | %.3g | %.3g | %.3g | %.0f | %.1f | %s | %s | %s |" % (
                r["method"], r["nonzeros"], r["newton_iterations"], r["krylov_iterations"], r["setup_seconds"],
                r["assembly_seconds"], r["linear_seconds"], r["wall_seconds"], r["peak_mb"],
                r["peak_mb"] * 1024 / r["particles"], "%.3e" % r["field_error"] if r.get("field_error") is not None else "–",
                r["path"].split(" -> ")[-1] if r["solver"] == "auto" else "",
                "%.1f → %.1f" % tuple(r["load"]) if "load" in r else "–"))
    out.append("")
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--command", required=True)
    ap.add_argument("--kernels", required=True)
    ap.add_argument("--kernels-native", help="kernel_bench_native's JSON (-march=native), for the flags table")
    ap.add_argument("--assembly", nargs="+", required=True)
    ap.add_argument("--solves", nargs="*", default=[], help="JSON lines of bench/solve_bench.py")
    ap.add_argument("--profile", nargs="*", default=[], help="markdown files appended as they are")
    ap.add_argument("--build", default="build")
    ap.add_argument("--seconds", type=float, default=0)
    a = ap.parse_args()
    _, context = load_runs([a.kernels])
    out = ["# Performance\n",
           "Written by `%s` (bench/run.sh → Google Benchmark → bench/report.py) — do not edit by hand; the profile "
           "section comes from `bench/profile.md` (written by `bench/profile.sh`). Medians of the repetitions of one "
           "run; the machine is shared, so compare ratios within one run, not absolute times across runs.\n" % a.command]
    out += machine_lines(context, a.build, a.seconds, a.command)
    out.append("")
    out += kernel_section(a.kernels)
    if a.kernels_native and os.path.exists(a.kernels_native):
        out += native_section(a.kernels, a.kernels_native)
    out += assembly_section(a.assembly)
    out += solve_section(a.solves)
    for path in a.profile:
        if os.path.exists(path):
            out.append(open(path).read().rstrip() + "\n")
    out += ["## Recorded elsewhere (not re-measured by this suite)\n",
            "- CHOLMOD's supernodal factorisation is about 4× faster with OpenBLAS than with the reference BLAS, which is "
            "why `scripts/install_deps.sh` installs `libopenblas0-pthread`.",
            "- Colouring against atomic adds in the stiffness assembly (the first runtime's assembler, 100² at delta/h = 3.5 "
            "and 200² at 1.5): `runtime/assembly/assembler.hpp`.\n"]
    print("\n".join(out))


if __name__ == "__main__":
    main()
