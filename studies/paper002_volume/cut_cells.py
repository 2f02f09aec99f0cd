# Table 2.2's AI error split into (share of the sphere's volume in cut cells) x (error per unit of cut-cell
# volume), for the paper's column and ours (docs/paper002.md, "Why our AI rate is 1"). delta = 18h, dx = delta/m.
# Usage: /usr/bin/python3 studies/paper002_volume/cut_cells.py
import math
paper = {3:0.050,4:0.029,5:0.025,6:0.017,8:0.011,9:0.009,10:0.007,15:0.003,20:0.002,30:0.001}
rows=[]
for m,err in paper.items():
    n = m+1
    cut = 0; inside_part = 0.0
    for i in range(-n,n+1):
        for j in range(-n,n+1):
            for k in range(-n,n+1):
                near = sum(max(0.0,abs(c)-0.5)**2 for c in (i,j,k))
                far = sum((abs(c)+0.5)**2 for c in (i,j,k))
                if near < m*m and far > m*m: cut += 1
    V = 4/3*math.pi*m**3
    frac = cut / V
    rows.append((m, cut, frac, err, err/100/frac))
    print(f"| δ/{m} | {cut} | {frac:.3f} | {err:.3f} | {err/100/frac:.2e} |")
ours = {3: (0.0911, 0.0012), 4: (0.0654, 0.0008), 5: (0.0452, 0.0002), 6: (0.0482, 0.0006), 8: (0.0319, 0.0004),
        9: (0.0312, 0.0004), 10: (0.0317, 0.0002), 15: (0.0167, 0.0002), 20: (0.0126, 0.0002), 30: (0.0089, 0.0001)}
def slope(xs, ys):
    x = [math.log(a) for a in xs]; y = [math.log(b) for b in ys]; n = len(x); mx = sum(x) / n; my = sum(y) / n
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)
dx = [18 / r[0] for r in rows]
print("rate of the paper's AI error:", round(slope(dx, [r[3] for r in rows]), 2))
print("rate of the cut-cell share:", round(slope(dx, [r[2] for r in rows]), 2))
print("rate of the paper's error per unit cut-cell volume:", round(slope(dx, [r[4] for r in rows]), 2))
print("ours, EPS = 1e-2, per unit cut-cell volume:", ", ".join(f"{ours[r[0]][0] / 100 / r[2]:.1e}" for r in rows),
      "rate", round(slope(dx, [ours[r[0]][0] / r[2] for r in rows]), 2))
print("ours, EPS = 1e-4, per unit cut-cell volume:", ", ".join(f"{ours[r[0]][1] / 100 / r[2]:.1e}" for r in rows))
