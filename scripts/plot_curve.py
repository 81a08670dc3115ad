#!/usr/bin/env python3
"""Plot flume curves (one per scheme), against reference data when given (used by `flume validate`:
probes against their references, and diagnostics such as the angular momentum of BL Fig 6)."""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [float(r["x"]) for r in rows], [float(r["y"]) for r in rows]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--series", action="append", default=[], help="LABEL=CSV (columns x,y)")
    ap.add_argument("--reference")
    ap.add_argument("--reference-label", default="reference")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="")
    ap.add_argument("--xlabel", default="x")
    ap.add_argument("--ylabel", default="y")
    a = ap.parse_args()
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    rx, ry = read(a.reference) if a.reference else ([], [])
    xmax = 1.15 * max(rx) if rx else None  # the compared window; the run may go on beyond it
    shown = list(ry)
    for k, item in enumerate(a.series):
        label, path = item.split("=", 1)
        x, y = read(path)
        ax.plot(x, y, "-", lw=2.0 if k == 0 else 1.2, label="flume " + label)
        if xmax is None:
            xmax = max(x)
        shown += [v for u, v in zip(x, y) if u <= xmax]
    if rx:
        ax.plot(rx, ry, "o", color="black", mfc="none", label=a.reference_label)
    ax.set_xlim(0.0, xmax)
    pad = 0.05 * (max(shown) - min(shown))
    ax.set_ylim(min(shown) - pad, max(shown) + pad)
    ax.set_xlabel(a.xlabel)
    ax.set_ylabel(a.ylabel)
    ax.set_title(a.title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
