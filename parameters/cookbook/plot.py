#!/usr/bin/env python3
"""Runs every recipe of parameters/cookbook/ from the repository's root and
draws, per recipe, its deflection field (a map over the plate) and its
deflection along the profile line (the centre line y = Ly/2 by default);
the thickness recipe with each of its three models:

  /usr/bin/python3 parameters/cookbook/plot.py [build/nitsche-contact] [results/cookbook-plot]

writes OUT/cookbook_NAME.png (doc/img/ holds copies, shown in
doc/cookbook.md) and each run's output directory under OUT."""
import csv
import math
import os
import re
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "..", ".."))
exe = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "nitsche-contact"))
out = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "results/cookbook-plot")
os.makedirs(out, exist_ok=True)


def run(name, text):
    """Run text (from the repository's root, where the recipes' relative
    paths start) with its output in OUT/name; None if the run fails, else
    the profile as (x, w) lists and the field as (x, y, W) with NaN off the
    plate."""
    outdir = os.path.join(out, name)
    prm = os.path.join(out, name + ".prm")
    with open(prm, "w") as f:
        f.write(text + "\nsubsection Output\n  set Directory = %s\n  set Format = none\n"
                "  set Profile points = 201\n  set Field grid points = 81\nend\n" % outdir)
    with open(os.path.join(out, name + ".log"), "w") as log:
        if subprocess.run([exe, prm], stdout=log, stderr=subprocess.STDOUT, cwd=root).returncode != 0:
            print("%s: the run failed, see %s.log" % (name, os.path.join(out, name)))
            return None
    rows = list(csv.DictReader(open(os.path.join(outdir, "profile.csv"))))
    profile = [float(r["x"]) for r in rows], [float(r["deflection"]) for r in rows]
    rows = list(csv.DictReader(open(os.path.join(outdir, "field.csv"))))
    x = sorted({float(r["x"]) for r in rows})
    y = sorted({float(r["y"]) for r in rows})
    W = np.full((len(y), len(x)), np.nan)
    ix = {v: i for i, v in enumerate(x)}
    iy = {v: j for j, v in enumerate(y)}
    for r in rows:
        W[iy[float(r["y"])], ix[float(r["x"])]] = float(r["deflection"])
    return profile, (np.array(x), np.array(y), W)


def broken(xs, ws):
    """The profile with NaN where points off the plate were left out, so
    that the curve is not drawn across a hole."""
    step = min(b - a for a, b in zip(xs, xs[1:]) if b > a)
    X, W = [xs[0]], [ws[0]]
    for a, b, w in zip(xs, xs[1:], ws[1:]):
        if b - a > 1.5 * step:
            X.append(math.nan)
            W.append(math.nan)
        X.append(b)
        W.append(w)
    return X, W


for name in sorted(f[:-4] for f in os.listdir(here) if f.endswith(".prm")):
    text = open(os.path.join(here, name + ".prm")).read()
    models = ("mindlin", "kirchhoff", "elasticity") if name == "thickness" else (None,)
    results = []
    for model in models:
        if model is None:
            results.append((None, run(name, text)))
        else:
            results.append((model, run(name + "_" + model,
                                       re.sub(r"(?m)^set Model = .*$", "set Model = " + model, text))))
    results = [(m, r) for m, r in results if r]
    if not results:
        continue
    fig, (map_ax, line_ax) = plt.subplots(1, 2, figsize=(9, 3.6))
    x, y, W = results[0][1][1]
    image = map_ax.contourf(x, y, np.ma.masked_invalid(W), 30, cmap="viridis")
    bar = fig.colorbar(image, ax=map_ax)
    bar.ax.tick_params(labelsize=7)
    map_ax.set_aspect("equal")
    map_ax.set_title("deflection" + (" (%s)" % results[0][0] if results[0][0] else ""), fontsize=9)
    map_ax.set_xlabel("x", fontsize=8)
    map_ax.set_ylabel("y", fontsize=8)
    for model, (profile, _) in results:
        line_ax.plot(*broken(*profile), label=model)
    if len(results) > 1:
        line_ax.legend(fontsize=7)
    line_ax.set_title("along the profile line", fontsize=9)
    line_ax.set_xlabel("x on the profile line", fontsize=8)
    line_ax.set_ylabel("deflection", fontsize=8)
    for ax in (map_ax, line_ax):
        ax.tick_params(labelsize=7)
    fig.suptitle("parameters/cookbook/%s.prm" % name, fontsize=10)
    fig.tight_layout()
    path = os.path.join(out, "cookbook_%s.png" % name)
    fig.savefig(path, dpi=90)
    plt.close(fig)
    print("wrote", path)
