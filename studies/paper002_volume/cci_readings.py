#!/usr/bin/python3
"""Which reading of the paper's cubic-cell integration (CCI) gives its Table 2.2/2.3 errors.

For delta = m dx on a unit lattice, the horizon-sphere volume by eq. (2.16) summed over
  (a) the nodes with |xi| <= delta only (the paper's CCI: reproduces every printed digit), and
  (b) the nodes with |xi| <= delta + dx/2 (eq. 2.16 as written; the runtime's partial_linear),
both with the source node. Run: /usr/bin/python3 studies/paper002_volume/cci_readings.py
"""
import math

import numpy as np

PAPER = {3: 7.992, 4: 10.525, 5: 7.966, 6: 4.891, 8: 5.367, 9: 3.773, 10: 3.862, 15: 2.415, 20: 2.028, 30: 1.251}

print("| m | (a) within delta, % | paper CCI, % | (b) to delta + dx/2, % |")
print("|---|---|---|---|")
for m, paper in PAPER.items():
    r = np.arange(-m - 1, m + 2)
    x, y, z = np.meshgrid(r, r, r, indexing="ij")
    length = np.sqrt(x**2 + y**2 + z**2)
    beta = np.clip(m + 0.5 - length, 0.0, 1.0)
    exact = 4.0 / 3.0 * math.pi * m**3
    within = beta[length <= m * (1 + 1e-12)].sum()
    searched = beta[length <= m + 0.5].sum()
    print(f"| {m} | {100 * abs(within - exact) / exact:.3f} | {paper:.3f} | {100 * abs(searched - exact) / exact:.3f} |")
