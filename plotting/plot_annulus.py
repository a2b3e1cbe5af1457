#!/usr/bin/python3
"""plot_annulus.py — fig 19 of [Lagrangian]: annulus displacement error against h (docs/results/annulus.csv)
and the observed rates between successive meshes. Writes docs/results/annulus.png and prints the rates."""
import csv, math
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

rows = [r for r in csv.DictReader(open('docs/results/annulus.csv')) if r['error'] and r['rc'] == '0']
fig, ax = plt.subplots(figsize=(5.5, 4.2))
for m in ['1', '4', '8', '9', '16']:
    pts = sorted(((float(r['h']), float(r['error'])) for r in rows if r['mpTri'] == m), reverse=True)
    if not pts:
        continue
    ax.loglog([p[0] for p in pts], [p[1] for p in pts], 'o-', label=f'{m} points per triangle')
    rates = [math.log(pts[i + 1][1] / pts[i][1]) / math.log(pts[i + 1][0] / pts[i][0]) for i in range(len(pts) - 1)]
    print(m, 'rates (coarse to fine):', ' '.join(f'{r:.2f}' for r in rates))
h0 = 0.43633
ax.loglog([h0, h0 / 8], [1.2e-2, 1.2e-2 / 64], 'k--', label='slope 2')
ax.set_xlabel('h (m)'); ax.set_ylabel('error = sum |u_p - u_a(X_p)| V0_p / V0 (m)')
ax.set_title('annulus, standard MPM, UL, alpha = 0.1 in 10 steps')
ax.legend(fontsize=8); fig.tight_layout(); fig.savefig('docs/results/annulus.png', dpi=120)
