#!/usr/bin/env python3
"""Every shape of 'Geometry/Shape' with the membrane model: a membrane of
tension 1 under the load -0.02, on the plane z = -0.06 (the disk and the
annulus: radius 5 around (5, 5)), each edge clamped except the holes, which
are free. Draws the deflection field of
each on one figure:

  /usr/bin/python3 parameters/shapes.py [build/nitsche-contact] [results/shapes]

writes OUT/shapes.png (doc/img/shapes.png is a copy, in doc/geometry.md),
OUT/shapes.md (a table of DoFs, Newton iterations, reaction) and each run's
output under OUT/NAME. Runs from the repository's root, where the mesh
file's relative path starts."""
import csv
import json
import os
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, ".."))
exe = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "nitsche-contact"))
out = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "results/shapes")
os.makedirs(out, exist_ok=True)

SHAPES = [
    ("rectangle", "set Shape = rectangle", "all: clamped"),
    ("disk", "set Shape = disk", "all: clamped"),
    ("annulus", "set Shape = annulus\n  set Inner radius = 2", "0: clamped; 1: free"),
    ("L-shape", "set Shape = L-shape", "all: clamped"),
    ("rectangle with hole", "set Shape = rectangle with hole\n  set Hole size = 2.5, 2.5",
     "4: free; all: clamped"),
    ("mesh file", "set Shape = mesh file\n  set Mesh file = parameters/meshes/plate_with_hole.msh",
     "1: clamped; 2: free"),
]
TEMPLATE = """set Model = membrane
subsection Geometry
  %s
  set Boundary conditions = %s
  set Initial refinement = %d
  set Number of cycles = 3
end
subsection Obstacle
  set Type = plane
  set Level = -0.06
end
subsection Output
  set Directory = %s
  set Format = vtu
  set Field grid points = 121
end
"""

fig, axes = plt.subplots(2, 3, figsize=(12, 7.4))
rows = []
for ax, (name, shape, conditions) in zip(axes.flat, SHAPES):
    tag = name.replace(" ", "_")
    outdir = os.path.join(out, tag)
    prm = os.path.join(out, tag + ".prm")
    # about as many cells on every shape: the disk's and the annulus's
    # coarse meshes have 12 and 8 cells, the others 64
    refinement = 2 if name in ("disk", "annulus") else 0
    with open(prm, "w") as f:
        f.write(TEMPLATE % (shape, conditions, refinement, outdir))
    with open(os.path.join(out, tag + ".log"), "w") as log:
        status = subprocess.run([exe, prm], stdout=log, stderr=subprocess.STDOUT, cwd=root).returncode
    if status != 0:
        print("%s: the run failed (status %d), see %s.log" % (name, status, outdir))
        ax.set_title(name + ": failed")
        continue
    cycle = json.load(open(os.path.join(outdir, "summary.json")))["cycles"][-1]
    rows.append((name, cycle["n_dofs"], cycle["nonlinear_iterations"], cycle["contact_force"],
                 cycle["contact_area"]))
    data = list(csv.DictReader(open(os.path.join(outdir, "field.csv"))))
    x = sorted({float(r["x"]) for r in data})
    y = sorted({float(r["y"]) for r in data})
    W = np.full((len(y), len(x)), np.nan)
    ix = {v: i for i, v in enumerate(x)}
    iy = {v: j for j, v in enumerate(y)}
    for r in data:
        W[iy[float(r["y"])], ix[float(r["x"])]] = float(r["deflection"])
    image = ax.contourf(x, y, np.ma.masked_invalid(W), 30, cmap="viridis", vmin=-0.06, vmax=0)
    if np.nanmin(W) < -0.0599:
        ax.contour(x, y, np.ma.masked_invalid(W), levels=[-0.0599], colors="white", linewidths=0.8)
    ax.set_aspect("equal")
    ax.set_xlim(-0.2, 10.2)
    ax.set_ylim(-0.2, 10.2)
    ax.set_title("Shape = %s" % name, fontsize=10)
    ax.tick_params(labelsize=7)
fig.colorbar(image, ax=axes, shrink=0.8, label="deflection (white: on the obstacle)")
fig.suptitle("The membrane on every shape: load -0.02, plane z = -0.06")
path = os.path.join(out, "shapes.png")
fig.savefig(path, dpi=80)
with open(os.path.join(out, "shapes.md"), "w") as f:
    f.write("| shape | DoFs | Newton its (last cycle) | reaction | contact area |\n|---|---|---|---|---|\n")
    for r in rows:
        f.write("| %s | %d | %d | %.5f | %.4f |\n" % r)
print("wrote", path, "and", os.path.join(out, "shapes.md"))
