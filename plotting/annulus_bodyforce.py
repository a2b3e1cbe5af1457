#!/usr/bin/python3
"""annulus_bodyforce.py — the body force of the manufactured annulus ([Lagrangian] sec 7.4, eq 44).

Derivation (docs/annulus.md): the motion x = Q(theta(R)) X with
theta = alpha 16 (R-Ri)^2 (R-Ro)^2 / (Ri-Ro)^4 keeps every radius (r = R) and turns the
circle R by theta(R). In the local polar bases (E_R, E_Theta) at X and (e_r, e_phi) at x,
    F = e_r (x) E_R + e_phi (x) E_Theta + gamma e_phi (x) E_R,   gamma = R theta'(R),
a simple shear of amount gamma: J = 1. Hencky elasticity: tau = D : eps, eps = 1/2 ln(F F^T),
sigma = tau / J. Since tr eps = ln J = 0, sigma = 2 G eps (any nu, plane strain), and
    eps = f(gamma) [[-gamma/2, 1], [1, gamma/2]]  (e_r, e_phi),  f = asinh(gamma/2)/sqrt(1+gamma^2/4).
Equilibrium in the current configuration, div_x sigma + b = 0, in polar coordinates
(sigma depends on r only):
    b_r   = -(d sigma_rr/dr + (sigma_rr - sigma_pp)/r),
    b_phi = -(d sigma_rp/dr + 2 sigma_rp / r),
with r = R: b is a function of the reference position X (radius R, and the direction
e_phi at the current angle Theta + theta(R)).
This script checks eps (exp(2 eps) = F F^T), forms b_r, b_phi symbolically, prints them, checks
them against the Cartesian divergence of sigma(x) (sympy's F and sigma, differentiated by mpmath at
30 digits, d/dx_j = F^-1_Kj d/dX_K) at sample points, and prints reference values for the C++ test.
Run: /usr/bin/python3 plotting/annulus_bodyforce.py [--plot]
"""
import sys
import sympy as sp

R, Th, alpha, G, Ri, Ro, g = sp.symbols('R Theta alpha G R_i R_o gamma', real=True)
theta = alpha * 16 * (R - Ri)**2 * (R - Ro)**2 / (Ri - Ro)**4          # eq 44

# 1. Hencky strain of the simple shear gamma: closed form, checked by the matrix exponential
s = sp.sqrt(1 + g**2 / 4)
f = sp.asinh(g / 2) / s
eps = f * sp.Matrix([[-g / 2, 1], [1, g / 2]])
Bm = sp.Matrix([[1, g], [g, 1 + g**2]])
for gv in [0.05, 0.3, 1.7]:
    diff = (sp.exp(2 * eps.subs(g, gv)).evalf(30) - Bm.subs(g, gv)).norm()
    assert diff < 1e-12, diff  # exp of a double-precision matrix

# 2. stresses in (e_r, e_phi) as functions of R, and the body force
gam = R * sp.diff(theta, R)
sig = (2 * G * eps).subs(g, gam)
srr, srp, spp = sig[0, 0], sig[0, 1], sig[1, 1]
b_r = -(sp.diff(srr, R) + (srr - spp) / R)
b_p = -(sp.diff(srp, R) + 2 * srp / R)
print('gamma(R) =', sp.factor(gam))
print('b_r(R)   =', b_r)
print('b_phi(R) =', b_p)

# 3. independent check: Cartesian components, sigma(X) rotated to x, d/dx = dX/dx d/dX
X, Y = sp.symbols('X Y', real=True)
Rxy = sp.sqrt(X**2 + Y**2)
th = theta.subs(R, Rxy)
c, sn = sp.cos(th), sp.sin(th)
x = sp.Matrix([c * X - sn * Y, sn * X + c * Y])
F = x.jacobian([X, Y])
vals = {alpha: sp.Rational(1, 10), G: sp.Rational(1, 2), Ri: sp.Rational(3, 4), Ro: sp.Rational(5, 4)}
Fn = F.subs(vals)
phi = sp.atan2(x[1], x[0]).subs(vals)
Qc = sp.Matrix([[sp.cos(phi), -sp.sin(phi)], [sp.sin(phi), sp.cos(phi)]])  # (e_r, e_phi) -> xy
sigxy = Qc * sig.subs(vals).subs(R, Rxy) * Qc.T
import mpmath as mm
mm.mp.dps = 30
sfun = sp.lambdify((X, Y), sigxy, 'mpmath')          # sigma(X) in x, y components
Ffun = sp.lambdify((X, Y), Fn, 'mpmath')
samples = [(0.9, 0.2), (-0.4, 0.95), (0.1, -1.12)]
for Xv, Yv in samples:
    Finv = (mm.matrix(Ffun(mm.mpf(Xv), mm.mpf(Yv)))) ** -1
    divs = []
    for i in range(2):
        d = 0
        for j in range(2):
            dX = mm.diff(lambda u: sfun(u, mm.mpf(Yv))[i, j], mm.mpf(Xv))
            dY = mm.diff(lambda v: sfun(mm.mpf(Xv), v)[i, j], mm.mpf(Yv))
            d += dX * Finv[0, j] + dY * Finv[1, j]
        divs.append(-d)
    Rv = (Xv**2 + Yv**2)**0.5
    ph = float(phi.subs({X: Xv, Y: Yv}))
    br, bp = [float(e.subs(vals).subs(R, Rv)) for e in (b_r, b_p)]
    bx = br * mm.cos(ph) - bp * mm.sin(ph)
    by = br * mm.sin(ph) + bp * mm.cos(ph)
    print(f'X = ({Xv}, {Yv}): b polar -> ({float(bx):.15e}, {float(by):.15e}); '
          f'-div sigma -> ({float(divs[0]):.15e}, {float(divs[1]):.15e})')
    assert abs(float(bx) - float(divs[0])) < 1e-12 and abs(float(by) - float(divs[1])) < 1e-12

if '--plot' in sys.argv:
    import numpy as np
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fr = sp.lambdify(R, b_r.subs(vals), 'numpy')
    fp = sp.lambdify(R, b_p.subs(vals), 'numpy')
    ft = sp.lambdify(R, theta.subs(vals), 'numpy')
    r = np.linspace(0.75, 1.25, 201)
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.5))
    ax[0].plot(r, ft(r) * r, label='u_phi = R theta (approx. |u|)')
    ax[0].set_xlabel('R (m)'); ax[0].set_ylabel('m'); ax[0].legend()
    ax[1].plot(r, fr(r), label='b_r'); ax[1].plot(r, fp(r), label='b_phi')
    ax[1].set_xlabel('R (m)'); ax[1].set_ylabel('N/m3 (E = 1 Pa, alpha = 0.1)'); ax[1].legend()
    fig.tight_layout()
    fig.savefig('docs/results/annulus_bodyforce.png', dpi=120)
