#!/usr/bin/env python3
"""Summarises the outputs of bench/profile.sh (perf reports, perf annotate, cachegrind) as
bench/profile.md (bench/report.py embeds it in docs/performance.md, followed by the
hand-written conclusions in bench/profile_notes.md).

usage: profile_report.py build/bench/profile
"""
import json
import os
import re
import statistics
import sys
from collections import defaultdict

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SETUP = ("SparsityPattern::SparsityPattern", "block_base", "find_bonds", "FamilyColouring", "discretize", "introsort",
         "insertion_sort", "compute_moments", "Grid::Grid", "SparsityPattern::matrix", "local_entries", "std::sort")


def assembler_lines():
    """Line sets of assembler.cpp: the finite check (all_finite's body) and the scatter loop."""
    src = open(os.path.join(ROOT, "runtime/assembly/assembler.cpp")).read().splitlines()
    finite, scatter = set(), set()
    start = next(i for i, l in enumerate(src) if l.startswith("bool all_finite"))
    end = next(i for i in range(start, len(src)) if src[i] == "}")
    finite = set(range(start + 1, end + 2))
    s0 = next(i for i, l in enumerate(src) if "family_slots(p)" in l)
    s1 = next(i for i in range(s0, len(src)) if "if (f_loc)" in src[i])
    scatter = set(range(s0 + 1, s1 + 1))
    return finite, scatter


FINITE, SCATTER = assembler_lines()


def classify(sym, path, line):
    f = os.path.basename(path)
    if any(s in sym for s in SETUP):
        return "setup (bonds, pattern, slot table; once per grid)"
    if f == "assembler.cpp" and line in FINITE:
        return "finite check of the local matrix (`all_finite`)"
    if f == "assembler.cpp" and line in SCATTER:
        return "scatter into K's slots"
    if f == "local_matrix.hpp":
        return "`form_local_matrix`"
    if "_tangent" in sym or "generated" in path or re.match(r"(silling|oterkus|correspondence|bond_based|lps)\.cpp", f):
        return "generated tangent kernel"
    if f == "sparsity_pattern.hpp" and "for_each_family" in sym:
        return "scatter into K's slots"
    if f.startswith("family_gather"):
        return "family gather"
    if "memset" in sym or "memset" in f:
        return "zeroing K and f (`std::fill`)"
    if sym.startswith("[k]") or "kallsyms" in sym:
        return "operating system (page faults, interrupts)"
    if "gomp" in sym.lower() or "omp" in f:
        return "OpenMP runtime"
    if f in ("assembler.cpp", "family_gather.hpp"):
        return "family loop, other lines"
    return "other"


def perf_lines(path):
    """(percent, symbol, file, line) from `perf report -t @ --sort sym,srcline`."""
    rows = []
    for raw in open(path):
        parts = raw.rstrip("\n").split("@")
        if len(parts) < 3:
            continue
        try:
            pct = float(parts[0].strip().rstrip("%"))
        except ValueError:
            continue
        sym = parts[1].strip()
        m = re.match(r"\s*([^:\s]+):(\d+)", parts[2])
        rows.append((pct, sym, m.group(1) if m else parts[2].strip(), int(m.group(2)) if m else -1))
    return rows


def bench_median(path, prefix):
    data = json.load(open(path))
    entries = [b for b in data["benchmarks"] if b.get("run_type") != "aggregate" and b["name"].startswith(prefix)]
    ns = statistics.median(b["real_time"] * {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}[b["time_unit"]] for b in entries)
    return ns, entries[0]


def stiffness_perf(d):
    rows = perf_lines(os.path.join(d, "stiffness.lines"))
    ns_perf, _ = bench_median(os.path.join(d, "stiffness.json"), "stiffness/")
    ns, b = bench_median(os.path.join(d, "stiffness_clean.json"), "stiffness/")
    fam = b["particles"]
    share = defaultdict(float)
    for pct, sym, f, line in rows:
        share[classify(sym, f, line)] += pct
    setup = sum(v for k, v in share.items() if k.startswith("setup"))
    kernel = sum(v for k, v in share.items() if k.startswith("operating system"))
    total = sum(share.values())
    user = total - setup - kernel
    entries = b["local_entries_per_particle"]
    out = ["### Stiffness assembly: where the time goes (perf)\n",
           "Silling plane strain, 200² grid, delta/h = 3.5 (%.1f bonds and %.0f local-matrix entries per family, "
           "%.0f K nonzeros per particle), 1 thread, without perf: %.0f ms per assembly = %.1f µs per family = %.2f ns "
           "per local-matrix entry. The shares are of the user-space samples of the assembly; left out are the one-off "
           "setup (%.0f%% of all samples) and the kernel's (%.0f%%, nearly all in the VM's interrupt path that perf's own "
           "timer triggers: the assembly took %.0f ms under perf). ns = share × the time without perf.\n" % (
               b["bonds_per_particle"], entries, b["nonzeros_per_particle"], ns / 1e6, ns / fam / 1e3,
               ns / fam / entries, setup, kernel, ns_perf / 1e6),
           "| part | share | ns per family | ns per local-matrix entry |", "|---|---|---|---|"]
    for k, v in sorted(share.items(), key=lambda kv: -kv[1]):
        if k.startswith("setup") or k.startswith("operating system") or v < 0.3:
            continue
        frac = v / user
        out.append("| %s | %.1f%% | %.0f | %.2f |" % (k, 100 * frac, frac * ns / fam, frac * ns / fam / entries))
    out.append("")
    return out


def stiffness_cachegrind(d):
    path = os.path.join(d, "stiffness.cg")
    events, fl, fn = [], "", ""
    acc = defaultdict(lambda: None)
    for raw in open(path):
        if raw.startswith("events:"):
            events = raw.split()[1:]
        elif raw.startswith("fl="):
            fl = raw[3:].strip()
        elif raw.startswith("fn="):
            fn = raw[3:].strip()
        elif raw[:1].isdigit():
            parts = raw.split()
            counts = [int(x) for x in parts[1:]] + [0] * (len(events) - len(parts) + 1)
            key = classify(fn, fl, int(parts[0]))
            acc[key] = [a + c for a, c in zip(acc[key], counts)] if acc[key] else counts
    ns, b = bench_median(os.path.join(d, "stiffness_cg.json"), "stiffness/")
    assemblies = b["iterations"] + 1  # the warm-up call
    entries = b["local_entries_per_particle"] * b["particles"] * assemblies
    idx = {e: i for i, e in enumerate(events)}
    out = ["### Stiffness assembly: instructions and cache misses (cachegrind)\n",
           "Silling plane strain, 100² grid, delta/h = 3.5, 1 thread, %d assemblies; simulated D1 = 48 KiB 12-way, "
           "LL = 1 MiB 8-way (this CPU's L2). Per local-matrix entry (%.0f per family); *K* holds %.0f nonzeros = "
           "%.0f MB of values, far larger than L2:\n" % (assemblies, b["local_entries_per_particle"],
                                                           b["nonzeros_per_particle"] * b["particles"],
                                                           b["nonzeros_per_particle"] * b["particles"] * 8 / 1e6),
           "| part | instructions | loads | stores | D1 read misses | D1 write misses | L2 read misses | L2 write misses |",
           "|---|---|---|---|---|---|---|---|"]
    total_ir = sum(v[idx["Ir"]] for k, v in acc.items() if not k.startswith("setup"))
    for k, v in sorted(acc.items(), key=lambda kv: -kv[1][idx["Ir"]]):
        if k.startswith("setup") or v[idx["Ir"]] < 0.005 * total_ir:
            continue
        per = lambda e: v[idx[e]] / entries
        out.append("| %s | %.2f | %.2f | %.2f | %.3f | %.3f | %.3f | %.3f |" % (
            k, per("Ir"), per("Dr"), per("Dw"), per("D1mr"), per("D1mw"), per("DLmr"), per("DLmw")))
    out.append("| all per-assembly work | %.2f | | | | | | |" % (total_ir / entries))
    out.append("")
    return out


def dense_perf(d):
    out = ["### Dense local tangent at 28 bonds: tangent kernel against `form_local_matrix` (perf)\n",
           "| law | ns per family | generated tangent kernel | `form_local_matrix` | other |", "|---|---|---|---|---|"]
    for law in ("silling_plane_strain", "correspondence_plane_strain"):
        lines = os.path.join(d, "dense_%s.lines" % law)
        if not os.path.exists(lines):
            continue
        ns, _ = bench_median(os.path.join(d, "dense_%s.json" % law), "generated_tangent_dense/")
        share = defaultdict(float)
        for pct, sym, f, line in perf_lines(lines):
            c = classify(sym, f, line)
            share[c if c in ("generated tangent kernel", "`form_local_matrix`") else "other"] += pct
        t = sum(share.values())
        out.append("| %s | %.0f | %.0f%% | %.0f%% | %.0f%% |" % (
            law, ns, 100 * share["generated tangent kernel"] / t, 100 * share["`form_local_matrix`"] / t,
            100 * share["other"] / t))
    out.append("")
    return out


def divisions(d):
    path = os.path.join(d, "factors.annotate")
    if not os.path.exists(path):
        return []
    pct, ins = [], []
    for raw in open(path):
        a, _, rest = raw.partition(":")
        pct.append(float(a))
        ins.append(rest.split(":", 1)[1].strip() if ":" in rest else rest.strip())
    marks = set()
    for i, s in enumerate(ins):
        if re.match(r"v?(div|sqrt)[sp]d", s):
            marks.update({i, i + 1, i + 2})
    n_div = sum(1 for s in ins if re.match(r"v?div[sp]d", s))
    n_sqrt = sum(1 for s in ins if re.match(r"v?sqrt[sp]d", s))
    share = sum(pct[i] for i in marks if i < len(pct)) / sum(pct)
    return ["### Silling tangent kernel alone (perf annotate)\n",
            "`silling_plane_strain_intact_tangent` at 28 bonds: its loops hold %d `divsd` and %d `sqrtsd`; %.0f%% of "
            "the kernel's samples fall on a division or square root or on one of the two instructions after it (where a "
            "timer sample waiting for it lands), for %.0f%% of the instructions.\n" % (
                n_div, n_sqrt, 100 * share, 100 * len([i for i in marks if i < len(ins)]) / len(ins))]


def main():
    d = sys.argv[1]
    out = ["## Profile of the hottest paths\n",
           "Written by `bench/profile.sh` (build-prof/: the release flags plus `-g -fno-omit-frame-pointer`): "
           "`perf record -e cpu-clock` (this VM exposes no hardware counters to perf, so time is sampled and "
           "instruction and cache-miss counts come from `valgrind --tool=cachegrind`).\n"]
    out += stiffness_perf(d)
    out += stiffness_cachegrind(d)
    out += dense_perf(d)
    out += divisions(d)
    print("\n".join(out))


if __name__ == "__main__":
    main()
