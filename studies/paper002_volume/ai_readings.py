#!/usr/bin/python3
"""Paper 002 Table 2.2, AI column: readings of §2.4's adaptive stop tried against the paper's
errors (docs/paper002.md, "Readings of the AI stop rule").

The nested trapezoid of runtime/discretize/ai_volume.cpp, ported (the same cuts of each
direction where the limits change form, the Z extent exact), with the stop of §2.4
    if |I_{r-1}| > TOL: stop when |I_r - I_{r-1}| <= EPS |I_{r-1}|  else when <= EPS
read four ways:
  index  'double': M = 2^(n-1) subintervals at trapezoidal index n (the runtime's reading)
         'linear': M = n ("increase trapezoidal index by 1" with M the index itself)
  scope  'cell':   the test on each cut cell's volume fraction (the runtime's reading)
         'ball':   the test on the whole sphere's I, every cut cell at the same M
Usage: studies/paper002_volume/ai_readings.py [--eps 1e-1 1e-2 1e-3] [--grids 3 6 10 20 30]
       [--index double linear] [--scope cell ball]
"""
import argparse, math

PAPER = {3: 0.050, 4: 0.029, 5: 0.025, 6: 0.017, 8: 0.011, 9: 0.009, 10: 0.007, 15: 0.003, 20: 0.002, 30: 0.001}
TOL = 1e-4


def cut(a, b, squares):
    out = [a, b]
    for s in squares:
        if s > 0:
            r = math.sqrt(s)
            for x in (-r, r):
                if a < x < b:
                    out.append(x)
    return sorted(out)


def levels(lo, hi):
    out = [lo, hi]
    if lo < 0 < hi:
        out.append(0.0)
    return out


def trap(a, b, M, f):
    if b <= a:
        return 0.0
    step = (b - a) / M
    s = 0.5 * (f(a) + f(b)) + sum(f(a + k * step) for k in range(1, M))
    return s * step


def cell_volume(lo, hi, R, M):
    R2 = R * R
    xsq = [R2 - y * y - z * z for y in levels(lo[1], hi[1]) for z in levels(lo[2], hi[2])]
    zsq = [z * z for z in levels(lo[2], hi[2])]

    def length(x, y):
        s = math.sqrt(max(0.0, R2 - x * x - y * y))
        return max(0.0, min(hi[2], s) - max(lo[2], -s))

    def area(x):
        rho2 = max(0.0, R2 - x * x)
        rho = math.sqrt(rho2)
        ys = cut(max(lo[1], -rho), min(hi[1], rho), [rho2 - z2 for z2 in zsq])
        return sum(trap(ys[i], ys[i + 1], M, lambda y: length(x, y)) for i in range(len(ys) - 1))

    xs = cut(max(lo[0], -R), min(hi[0], R), xsq)
    return sum(trap(xs[i], xs[i + 1], M, area) for i in range(len(xs) - 1))


def cut_cells(m, delta):
    """Cells of the lattice dx = delta/m (a node at the centre) that the sphere's surface crosses,
    one octant with multiplicities (the sphere and the lattice share the octahedral symmetry)."""
    h = delta / m
    full, cut_list = 0.0, []
    for i in range(0, m + 2):
        for j in range(0, m + 2):
            for k in range(0, m + 2):
                mult = (1 if i == 0 else 2) * (1 if j == 0 else 2) * (1 if k == 0 else 2)
                c = (i * h, j * h, k * h)
                near2 = sum(max(0.0, abs(x) - h / 2) ** 2 for x in c)
                far2 = sum((abs(x) + h / 2) ** 2 for x in c)
                if near2 >= delta * delta:
                    continue
                if far2 <= delta * delta:
                    full += mult * h ** 3
                else:
                    cut_list.append((mult, [x - h / 2 for x in c], [x + h / 2 for x in c]))
    return h, full, cut_list


def M_of(index, n):
    return 1 << (n - 1) if index == 'double' else n


def stop(prev, cur, eps):
    change = abs(cur - prev)
    return change <= eps * abs(prev) if abs(prev) > TOL else change <= eps


def sphere(m, eps, index, scope, delta=18.0):
    h, full, cells = cut_cells(m, delta)
    cellv = h ** 3
    if scope == 'cell':
        total = full
        for mult, lo, hi in cells:
            prev = cell_volume(lo, hi, delta, M_of(index, 1)) / cellv
            for n in range(2, 40):
                cur = cell_volume(lo, hi, delta, M_of(index, n)) / cellv
                if stop(prev, cur, eps):
                    break
                prev = cur
            total += mult * cur * cellv
    else:
        def whole(n):
            return full + sum(mult * cell_volume(lo, hi, delta, M_of(index, n)) for mult, lo, hi in cells)
        prev = whole(1)
        for n in range(2, 40):
            cur = whole(n)
            if stop(prev, cur, eps):
                break
            prev = cur
        total = cur
    exact = 4.0 / 3.0 * math.pi * delta ** 3
    return 100.0 * abs(total - exact) / exact


def rate(grids, errs):
    xs = [math.log(18.0 / m) for m in grids]
    ys = [math.log(e) for e in errs]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--eps', type=float, nargs='+', default=[1e-2, 1e-3, 1e-4])
    ap.add_argument('--grids', type=int, nargs='+', default=[3, 6, 10, 20, 30])
    ap.add_argument('--index', nargs='+', default=['double', 'linear'])
    ap.add_argument('--scope', nargs='+', default=['cell', 'ball'])
    a = ap.parse_args()
    print('| index | scope | EPS | ' + ' | '.join(f'δ/{m}' for m in a.grids) + ' | rate | worst ratio to paper |')
    print('|---|---|---|' + '---|' * len(a.grids) + '---|---|')
    print('| paper | | | ' + ' | '.join(f'{PAPER[m]:.3f}' for m in a.grids)
          + f' | {rate(a.grids, [PAPER[m] for m in a.grids]):.2f} | |')
    for index in a.index:
        for scope in a.scope:
            for eps in a.eps:
                errs = [sphere(m, eps, index, scope) for m in a.grids]
                worst = max(max(e / PAPER[m], PAPER[m] / e) if e > 0 else float('inf') for e, m in zip(errs, a.grids))
                print(f'| {index} | {scope} | {eps:g} | ' + ' | '.join(f'{e:.4f}' for e in errs)
                      + f' | {rate(a.grids, errs):.2f} | {worst:.1f} |', flush=True)


if __name__ == '__main__':
    main()
