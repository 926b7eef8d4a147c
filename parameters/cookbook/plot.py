#!/usr/bin/env python3
"""Runs every recipe of parameters/cookbook/ and draws its deflection along
the profile line (the centre line y = Ly/2 by default) into one figure, a
panel per recipe (the thickness recipe with each of its three models):

  /usr/bin/python3 parameters/cookbook/plot.py [build/nitsche-contact] [results/cookbook-plot]

writes OUT/cookbook.png (doc/img/cookbook.png is a copy) and each run's
output directory under OUT."""
import csv
import os
import re
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "build", "nitsche-contact")
out = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "results/cookbook-plot")
os.makedirs(out, exist_ok=True)


def run(name, text):
    """Run text with its output in OUT/name; the profile as (s, w) lists."""
    outdir = os.path.join(out, name)
    prm = os.path.join(out, name + ".prm")
    with open(prm, "w") as f:
        f.write(text + "\nsubsection Output\n  set Directory = %s\n  set Format = none\n"
                "  set Profile points = 201\nend\n" % outdir)
    with open(os.path.join(out, name + ".log"), "w") as log:
        if subprocess.run([exe, prm], stdout=log, stderr=subprocess.STDOUT).returncode != 0:
            print("%s: the run failed, see %s.log" % (name, os.path.join(out, name)))
            return None
    rows = list(csv.DictReader(open(os.path.join(outdir, "profile.csv"))))
    return [float(r["x"]) for r in rows], [float(r["deflection"]) for r in rows]


names = sorted(f[:-4] for f in os.listdir(here) if f.endswith(".prm"))
fig, axes = plt.subplots(2, (len(names) + 1) // 2, figsize=(4 * ((len(names) + 1) // 2), 6.4),
                         squeeze=False)
for ax, name in zip(axes.flat, names):
    text = open(os.path.join(here, name + ".prm")).read()
    if name == "thickness":
        for model in ("mindlin", "kirchhoff", "elasticity"):
            curve = run(name + "_" + model,
                        re.sub(r"(?m)^set Model = .*$", "set Model = " + model, text))
            if curve:
                ax.plot(*curve, label=model)
        ax.legend(fontsize=7)
    else:
        curve = run(name, text)
        if curve:
            ax.plot(*curve)
    ax.set_title(name + ".prm", fontsize=9)
    ax.set_xlabel("x on the profile line", fontsize=8)
    ax.set_ylabel("deflection", fontsize=8)
    ax.tick_params(labelsize=7)
for ax in list(axes.flat)[len(names):]:
    ax.axis("off")
fig.suptitle("The cookbook recipes: deflection along the centre line (y = Ly/2)")
fig.tight_layout()
fig.savefig(os.path.join(out, "cookbook.png"), dpi=100)
print("wrote", os.path.join(out, "cookbook.png"))
