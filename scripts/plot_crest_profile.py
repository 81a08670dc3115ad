#!/usr/bin/env python3
"""Draw the surface near a solitary wave's crest against KdV's A sech^2((x - x_c) / lambda).

usage: plot_crest_profile.py --series LABEL=SNAPSHOTS.pvd [--series ...] --time T --depth H
           --rho0 RHO0 --dx DX --x-lo X0 --x-hi X1 [--periodic] --out OUT.png [--title TEXT]

For each series, the snapshot nearest T s: the depth of water along the tank from the
particles' masses, eta(x) = sum_i m_i B((x - x_i) / dx) / (rho0 dx), B the cubic B-spline of unit
integral, at the centres of the dx-wide columns (as flume's wave probes read it,
src/flume/probes/water_depth.hpp; mirror walls fold B back into the tank, a periodic tank wraps
it). The crest is the highest sample (refined by the parabola through it and its neighbours),
its height A = eta_max - H; KdV's wave of that height has the width lambda = sqrt(4 H^3 / (3 A))
(W (6.17)). Drawn against x - x_c: the surface (solid) and KdV's A sech^2 (dashed, same colour).
"""
import argparse
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_snapshot import read_vtu  # noqa: E402


def nearest_snapshot(pvd, t):
    entries = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(pvd).read())
    when, f = min(entries, key=lambda e: abs(float(e[0]) - t))
    return float(when), os.path.join(os.path.dirname(pvd), f)


def bspline(q):
    q = np.abs(q)
    return np.where(q < 1.0, 2.0 / 3.0 - q * q + 0.5 * q ** 3,
                    np.where(q < 2.0, (2.0 - q) ** 3 / 6.0, 0.0))


def depth(x, m, rho0, dx, x_lo, x_hi, periodic):
    n = max(1, int(round((x_hi - x_lo) / dx)))
    xc = x_lo + (np.arange(n) + 0.5) * dx
    if periodic:
        length = x_hi - x_lo
        images = [x, x - length, x + length]
    else:
        images = [x, 2.0 * x_lo - x, 2.0 * x_hi - x]
    eta = np.zeros(n)
    for xs in images:
        near = np.abs(xs[None, :] - xc[:, None]) < 2.0 * dx
        eta += np.where(near, bspline((xc[:, None] - xs[None, :]) / dx), 0.0) @ m
    return xc, eta / (rho0 * dx)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--series", action="append", default=[])
    ap.add_argument("--time", type=float, required=True)
    ap.add_argument("--depth", type=float, required=True)
    ap.add_argument("--rho0", type=float, required=True)
    ap.add_argument("--dx", type=float, required=True)
    ap.add_argument("--x-lo", type=float, required=True)
    ap.add_argument("--x-hi", type=float, required=True)
    ap.add_argument("--periodic", action="store_true")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    h = a.depth
    fig, ax = plt.subplots(figsize=(8, 3.6))
    reach = 0.0
    for k, spec in enumerate(a.series):
        label, pvd = spec.split("=", 1)
        when, path = nearest_snapshot(pvd, a.time)
        d = read_vtu(path)
        x = np.array([p[0] for p in d["Points"]])
        m = np.array(d["mass"])
        xc, eta = depth(x, m, a.rho0, a.dx, a.x_lo, a.x_hi, a.periodic)
        c = int(np.argmax(eta))
        x_c, top = xc[c], eta[c]
        if 0 < c < len(eta) - 1:
            lo, mid, hi = eta[c - 1], eta[c], eta[c + 1]
            den = lo - 2.0 * mid + hi
            off = 0.5 * (lo - hi) / den if den < 0.0 else 0.0
            x_c, top = xc[c] + off * a.dx, mid - 0.25 * (lo - hi) * off
        amp = top - h
        if not amp > 0.0:
            continue
        lam = np.sqrt(4.0 * h ** 3 / (3.0 * amp))
        reach = max(reach, 4.0 * lam)
        colour = "C%d" % k
        s = xc - x_c
        ax.plot(s, eta - h, colour, lw=1.2,
                label="%s, t = %.3g s: A = %.4f m" % (label, when, amp))
        ss = np.linspace(-4.0 * lam, 4.0 * lam, 400)
        ax.plot(ss, amp / np.cosh(ss / lam) ** 2, colour, ls="--", lw=1.0,
                label="KdV A sech^2((x - x_c) / lambda), lambda = %.3f m" % lam)
    if reach > 0.0:
        ax.set_xlim(-reach, reach)
    ax.axhline(0.0, color="0.6", lw=0.6)
    ax.set_xlabel("x - x_c (m)")
    ax.set_ylabel("eta - H (m)")
    ax.set_title(a.title, fontsize=8)
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)


if __name__ == "__main__":
    main()
