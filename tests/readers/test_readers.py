#!/usr/bin/env python3
"""The files flume writes, opened by the readers users have (issue "runs that survive", item 6):
every snapshot of the series with VTK's own XML reader (python3-vtk9), the newest checkpoint
with h5py (python3-h5py), the CSV tables with Python's csv module. Point counts and field names
must be flume's; values are checked against flume's own diagnostics.csv: the snapshot's total
mass and kinetic energy (sum m, sum m |v|^2 / 2) to 1e-12 relative (the same doubles summed in
another order: round-off), its density range exactly (min and max of the same values).

Usage: test_readers.py FLUME_BINARY
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import h5py
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

CASE = """
[case]
name = "readers"
end_time = 0.03
[particles]
spacing = 0.004
[scheme]
preset = "continuity"
[fluid]
viscosity = 0.5
[domain]
min = [0.0, 0.0]
max = [0.2, 0.1]
[[fluid_blocks]]
min = [0.0, 0.0]
max = [0.05, 0.05]
[output]
interval = 0.005
snapshot_interval = 0.01
[probes]
surge_front = true
[checkpoint]
every_steps = 10
"""

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def read_table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    check(all(len(r) == len(header) for r in body), f"{path}: every row as long as the header")
    return header, [[float(x) for x in r] for r in body]


def main():
    flume = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        case = os.path.join(tmp, "case.toml")
        with open(case, "w") as f:
            f.write(CASE)
        run = os.path.join(tmp, "run")
        subprocess.run([flume, "run", case, "--quiet", "--out", run], check=True)
        summary = json.load(open(os.path.join(run, "summary.json")))
        n = summary["particles"]
        check(summary["status"] == "completed", "the run completed")

        # CSV tables, with the contract's columns.
        header, diag = read_table(os.path.join(run, "diagnostics.csv"))
        for col in ["time", "step", "dt", "particles", "mass", "momentum_x", "momentum_y",
                    "angular_momentum", "kinetic_energy", "potential_energy", "internal_energy",
                    "rho_min", "rho_max"]:
            check(col in header, f"diagnostics.csv has {col}")
        probes_header, probes = read_table(os.path.join(run, "probes.csv"))
        check(probes_header == ["time", "surge_front"], "probes.csv columns")
        check(len(probes) == len(diag), "a probes row for every diagnostics row")
        by_time = {row[header.index("time")]: row for row in diag}

        # Every snapshot of the series, through VTK's XML reader.
        pvd = ET.parse(os.path.join(run, "snapshots", "snapshots.pvd")).getroot()
        entries = pvd.find("Collection").findall("DataSet")
        check(len(entries) == 4, f"4 snapshots listed (t = 0, 0.01, 0.02, 0.03): {len(entries)}")
        for e in entries:
            t = float(e.get("timestep"))
            reader = vtkXMLUnstructuredGridReader()
            reader.SetFileName(os.path.join(run, "snapshots", e.get("file")))
            reader.Update()
            grid = reader.GetOutput()
            check(grid.GetNumberOfPoints() == n, f"t = {t}: {n} points")
            pd = grid.GetPointData()
            names = sorted(pd.GetArrayName(k) for k in range(pd.GetNumberOfArrays()))
            check(names == ["density", "id", "mass", "pressure", "velocity"],
                  f"t = {t}: arrays {names}")
            m = vtk_to_numpy(pd.GetArray("mass"))
            v = vtk_to_numpy(pd.GetArray("velocity"))
            rho = vtk_to_numpy(pd.GetArray("density"))
            ids = vtk_to_numpy(pd.GetArray("id"))
            check(sorted(ids.tolist()) == list(range(n)), f"t = {t}: every id once")
            row = by_time.get(t)
            check(row is not None, f"t = {t}: a diagnostics row at the snapshot's time")
            if row is None:
                continue
            check(close(float(np.sum(m)), row[header.index("mass")], 1e-12), f"t = {t}: mass")
            ke = 0.5 * float(np.sum(m * np.sum(v * v, axis=1)))
            check(close(ke, row[header.index("kinetic_energy")], 1e-12) or
                  (ke == 0.0 and row[header.index("kinetic_energy")] == 0.0),
                  f"t = {t}: kinetic energy {ke} vs {row[header.index('kinetic_energy')]}")
            check(float(rho.min()) == row[header.index("rho_min")], f"t = {t}: rho_min")
            check(float(rho.max()) == row[header.index("rho_max")], f"t = {t}: rho_max")

        # The newest checkpoint, through h5py.
        cps = sorted(os.listdir(os.path.join(run, "checkpoints")))
        check(len(cps) == 2, f"keep = 2 checkpoints: {cps}")
        with h5py.File(os.path.join(run, "checkpoints", cps[-1]), "r") as f:
            check(f.attrs["format"] == "flume checkpoint", "format attribute")
            check(int(f.attrs["dimension"]) == 2, "dimension attribute")
            check(f.attrs["case_name"] == "readers", "case_name attribute")
            check(f["case_toml"][()].decode() == open(os.path.join(run, "case.toml")).read(),
                  "the resolved case")
            step = int(f["state/step"][()])
            check(cps[-1] == f"checkpoint_{step:010d}.h5", "the file is named by its step")
            check(f["state/time"].attrs["unit"] == "s", "time's unit")
            parts = f["particles"]
            check(int(parts.attrs["n_real"]) == n, "n_real")
            check(sorted(parts.keys()) == ["h", "id", "m", "rho", "v", "v_half", "x"],
                  f"the continuity scheme's state fields: {sorted(parts.keys())}")
            check(parts["x"].shape == (n, 2) and parts["rho"].shape == (n,), "shapes")
            check(parts["x"].attrs["unit"] == "m" and parts["rho"].attrs["unit"] == "kg/m^3",
                  "units")
            check(close(float(np.sum(parts["m"][()])), diag[0][header.index("mass")], 1e-12),
                  "the checkpoint's mass")
    print(f"{len(failures)} failed" if failures else "all reader checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
