#!/usr/bin/env python3
"""Draw the particles of a flume snapshot (.vtu written by flume) coloured by a field.

usage: plot_snapshot.py SNAPSHOT.vtu OUT.png [--field pressure] [--xlim A B] [--ylim A B]
       plot_snapshot.py SNAPSHOTS.pvd OUT.png --time T ...   (the snapshot nearest to T s)
A field NAME_x, NAME_y or NAME_z is a component of the vector NAME (velocity_x: the horizontal
velocity); a vector field by its name alone is coloured by its magnitude.
"""
import os
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
    ap.add_argument("--time", type=float, help="with a .pvd: the snapshot nearest to this time")
    a = ap.parse_args()
    path = a.vtu
    if path.endswith(".pvd"):
        entries = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', open(path).read())
        t, f = min(entries, key=lambda e: abs(float(e[0]) - (a.time or 0.0)))
        path = os.path.join(os.path.dirname(path), f)
        a.title = a.title or "t = %.4g s" % float(t)
    d = read_vtu(path)
    pts = d["Points"]
    name, comp = a.field, None
    if name not in d and name[-2:] in ("_x", "_y", "_z"):
        name, comp = name[:-2], "xyz".index(name[-1])
    c = d[name]
    if comp is not None:
        c = [t[comp] for t in c]
    elif isinstance(c[0], tuple):
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
