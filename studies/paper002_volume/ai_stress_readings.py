#!/usr/bin/python3
"""Paper 002 §2.5.2, uniaxial state at delta/3: does a reading of the AI stop rule give the paper's
AI stress sigma22 = 100.81? The one-point-per-cell stress sigma = 1/2 sum_j V_j f(xi_j) (x) xi_j of the
PMB law (c = 18K/(pi delta^4), exact stretch) with V_j = the cell's volume fraction from
ai_readings.py's stop readings times h^3 (docs/paper002.md, "Readings of the AI stop rule").
The first row reproduces the runtime's `exact` column (102.52, -0.34).
Usage: studies/paper002_volume/ai_stress_readings.py
"""
import sys, math
sys.path.insert(0, __import__('os').path.dirname(__file__))
import ai_readings as A
delta, m = 18.0, 3
h = delta / m
E, nu = 1e5, 0.25
K = E / (3 * (1 - 2 * nu)); c = 18 * K / (math.pi * delta ** 4)
eps = [-2.5e-4, 1e-3, -2.5e-4]
def sigma(index, EPS):
    s = [[0.0]*3 for _ in range(3)]
    R = m + 1
    for i in range(-R, R + 1):
        for j in range(-R, R + 1):
            for k in range(-R, R + 1):
                if i == j == k == 0: continue
                cc = (i*h, j*h, k*h)
                near2 = sum(max(0.0, abs(x) - h/2)**2 for x in cc); far2 = sum((abs(x)+h/2)**2 for x in cc)
                if near2 >= delta*delta: continue
                if far2 <= delta*delta: frac = 1.0
                else:
                    lo = [x - h/2 for x in cc]; hi = [x + h/2 for x in cc]; cv = h**3
                    prev = A.cell_volume(lo, hi, delta, A.M_of(index, 1)) / cv
                    for n in range(2, 60):
                        cur = A.cell_volume(lo, hi, delta, A.M_of(index, n)) / cv
                        if A.stop(prev, cur, EPS): break
                        prev = cur
                    frac = cur
                xi = cc; Y = [xi[q]*(1+eps[q]) for q in range(3)]
                r = math.sqrt(sum(x*x for x in xi)); y = math.sqrt(sum(x*x for x in Y))
                st = (y - r) / r
                f = [c*st*Y[q]/y for q in range(3)]
                V = frac * h**3
                for a in range(3):
                    for b in range(3): s[a][b] += 0.5 * V * f[a] * xi[b]
    return s
for index, EPS in [('double', 1e-4), ('linear', 3e-4), ('linear', 1e-3), ('double', 1e-2)]:
    s = sigma(index, EPS)
    print(index, EPS, 'sigma22 = %.2f sigma11 = %.2f' % (s[1][1], s[0][0]))
