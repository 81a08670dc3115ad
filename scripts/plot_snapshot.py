#!/usr/bin/env python3
"""Draw the particles of a flume snapshot (.vtu written by flume) coloured by a field.

usage: plot_snapshot.py SNAPSHOT.vtu OUT.png [--field pressure] [--xlim A B] [--ylim A B]
"""
import argparse
import re
import struct

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_vtu(path):
    """Reads flume's raw-appended .vtu: returns points (list of (x, y, z)) and point fields."""
    data = open(path, "rb").read()
    head, _, tail = data.partition(b'<AppendedData encoding="raw">')
    blob = tail[tail.index(b"_") + 1:]
    text = head.decode()
    arrays = re.findall(r'<DataArray type="(\w+)" Name="(\w+)"[^>]*?NumberOfComponents="(\d+)"'
                        r'[^>]*?offset="(\d+)"', text)
    out = {}
    for typ, name, ncomp, offset in arrays:
        off = int(offset)
        nbytes = struct.unpack_from("<Q", blob, off)[0]
        fmt = {"Float64": "d", "Int64": "q", "UInt8": "B"}[typ]
        count = nbytes // struct.calcsize(fmt)
        vals = struct.unpack_from("<%d%s" % (count, fmt), blob, off + 8)
        k = int(ncomp)
        out[name] = [vals[i:i + k] for i in range(0, count, k)] if k > 1 else list(vals)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("vtu")
    ap.add_argument("out")
    ap.add_argument("--field", default="pressure")
    ap.add_argument("--xlim", nargs=2, type=float)
    ap.add_argument("--ylim", nargs=2, type=float)
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    d = read_vtu(a.vtu)
    pts = d["Points"]
    c = d[a.field]
    if isinstance(c[0], tuple):
        c = [sum(v * v for v in t) ** 0.5 for t in c]
    fig, ax = plt.subplots(figsize=(9, 3.2))
    sc = ax.scatter([p[0] for p in pts], [p[1] for p in pts], c=c, s=2, cmap="viridis")
    fig.colorbar(sc, ax=ax, label=a.field)
    ax.set_aspect("equal")
    if a.xlim:
        ax.set_xlim(*a.xlim)
    if a.ylim:
        ax.set_ylim(*a.ylim)
    ax.set_title(a.title or a.vtu, fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)


if __name__ == "__main__":
    main()
