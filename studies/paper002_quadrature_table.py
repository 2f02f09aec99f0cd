#!/usr/bin/python3
"""Paper 002's bond volume factors on paper 000's constant-strain problems (docs/paper002.md).

For every law given, problem (scenes/uniaxial, biaxial, shear) and domain.quadrature choice
(volume, partial_linear, partial_exact), runs `pd run` at the given counts (cubic influence,
delta/h = 3 unless --ratio) and prints one markdown table: the largest relative probe error
of the scene (paper 000 eq. 36 over the analytic value) at the finest count, the order (least-squares slope of log error against log h over
all counts) and the wall time of the finest run (setup + solve, from summary.json).

Usage: studies/paper002_quadrature_table.py PD_BINARY [--counts 10 20 40] [--ratio 3.0]
       [--laws silling_plane_strain ...] [--out DIR]
"""
import argparse, json, math, os, re, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, '..', 'scenes')
QUADRATURES = ['volume', 'partial_linear', 'partial_exact']


def variant(text, law, count, ratio, quadrature, out):
    text = re.sub(r'^law: .*$', f'law: {law}', text, flags=re.M)
    text = re.sub(r'^(\s*)count: \d+', rf'\g<1>count: {count}\n\g<1>quadrature: {quadrature}', text, count=1, flags=re.M)
    text = re.sub(r'^horizon: .*$', f'horizon: {{ratio: {ratio}}}', text, flags=re.M)
    text = re.sub(r'^output: .*$', f'output: {{directory: {out}, vtu: false, csv: false}}', text, flags=re.M)
    return text


def slope(h, e):
    x = [math.log(v) for v in h]
    y = [math.log(v) for v in e]
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('pd')
    ap.add_argument('--counts', type=int, nargs='+', default=[10, 20, 40])
    ap.add_argument('--ratio', type=float, default=3.0)
    ap.add_argument('--laws', nargs='+', default=['correspondence_plane_strain', 'silling_plane_strain',
                                                   'oterkus_plane_strain', 'lps_plane_strain', 'bond_based_constant_2d'])
    ap.add_argument('--out', default='out/paper002_quadrature')
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    print(f'delta/h = {a.ratio}, cubic influence, counts {a.counts}; e = largest relative probe error (paper 000 eq. 36) at count {a.counts[-1]}, '
          'order = slope of log e against log h, s = setup + solve seconds of the finest run\n')
    print('| problem | law | ' + ' | '.join(f'{q}: e, order, s' for q in QUADRATURES) + ' |')
    print('|---|---|' + '---|' * len(QUADRATURES))
    for problem in ['uniaxial', 'biaxial', 'shear']:
        text = open(os.path.join(SCENES, problem + '.yaml')).read()
        for law in a.laws:
            cells = []
            for q in QUADRATURES:
                errors, hs, seconds = [], [], 0.0
                for count in a.counts:
                    out = os.path.abspath(os.path.join(a.out, f'{problem}_{law}_{q}_{count}'))
                    scene = out + '.yaml'
                    with open(scene, 'w') as f:
                        f.write(variant(text, law, count, a.ratio, q, out))
                    r = subprocess.run([a.pd, 'run', scene], capture_output=True, text=True,
                                       env=dict(os.environ, OMP_WAIT_POLICY='PASSIVE'))
                    if r.returncode != 0:
                        sys.exit(f'{scene}: pd run failed ({r.returncode}):\n{r.stderr}')
                    s = json.load(open(os.path.join(out, 'summary.json')))
                    errors.append(max(abs(pr['error'] / pr['reference']) for pr in s['probes'] if 'reference' in pr))
                    hs.append(10.0 / count)
                    seconds = s['seconds']['setup'] + s['seconds']['solve']
                cells.append(f'{errors[-1]:.3e}, {slope(hs, errors):.2f}, {seconds:.2f}')
            print(f'| {problem} | {law} | ' + ' | '.join(cells) + ' |', flush=True)


if __name__ == '__main__':
    main()
