#!/usr/bin/env python3
"""Plot one flume probe curve against its reference data (used by `flume validate`)."""
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
    ap.add_argument("--flume", required=True)
    ap.add_argument("--reference", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="")
    ap.add_argument("--xlabel", default="x")
    ap.add_argument("--ylabel", default="y")
    ap.add_argument("--reference-label", default="reference")
    a = ap.parse_args()
    fx, fy = read(a.flume)
    rx, ry = read(a.reference)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(fx, fy, "-", color="tab:blue", label="flume")
    ax.plot(rx, ry, "o", color="black", mfc="none", label=a.reference_label)
    ax.set_xlabel(a.xlabel)
    ax.set_ylabel(a.ylabel)
    ax.set_title(a.title, fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
