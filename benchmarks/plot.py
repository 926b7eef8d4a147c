#!/usr/bin/env python3
"""Plot doc/benchmarks.csv (measured run times of the models on the paper's
test against their finest number of DoFs) into doc/img/benchmarks.png.
usage: python3 benchmarks/plot.py [csv] [png]"""
import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "doc", "benchmarks.csv")
dst = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "doc", "img", "benchmarks.png")

runs = {}
with open(src) as f:
    for row in csv.DictReader(line for line in f if not line.startswith("#")):
        runs.setdefault(row["model"], []).append(
            (int(row["finest_dofs"]), float(row["seconds"]), int(row["newton_its_finest"])))

fig, (ax_t, ax_n) = plt.subplots(1, 2, figsize=(11, 4.2))
# more runs than the 10 colours of the default cycle: the colour map
# tab20 and, past 10 runs, squares on dashed lines
for i, (model, pts) in enumerate(runs.items()):
    pts.sort()
    dofs = [p[0] for p in pts]
    style = dict(color=plt.cm.tab20(i % 20), marker="o" if i < 10 else "s",
                 ls="-" if i < 10 else "--", label=model)
    ax_t.loglog(dofs, [p[1] for p in pts], **style)
    ax_n.semilogx(dofs, [p[2] for p in pts], **style)
ax_t.axhline(60, color="grey", ls="--", lw=0.8)
ax_t.axvline(1e6, color="grey", ls=":", lw=0.8)
ax_t.set_xlabel("DoFs of the finest cycle")
ax_t.set_ylabel("seconds, nested run up to that cycle")
ax_t.set_title("time (dashed: 60 s)")
ax_n.axhline(3, color="grey", ls="--", lw=0.8)
ax_n.set_xlabel("DoFs of the cycle")
ax_n.set_ylabel("Newton iterations on that cycle")
ax_n.set_title("Newton iterations (dashed: 3)")
ax_n.legend(fontsize=7)
for ax in (ax_t, ax_n):
    ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(dst, dpi=110)
print("wrote", dst)
