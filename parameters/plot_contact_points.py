#!/usr/bin/env python3
"""Map of the contact status from the contact_points-NN.csv files that
'Output/Contact points = true' writes (one panel per file).

Each node of the contact face can carry several quadrature points (one per
cell or face sharing it, with the vertex and Gauss-Lobatto rules); a
location is drawn red when all of its points are active, orange when some
are, grey when none is. The legend of each panel gives the number of
points, of active points and of inactive points with 0 < gap < 1e-6 (the
plate lifted off by less than a micro-unit, at the round-off level of the
deflections of a thin plate).

usage: plot_contact_points.py FILE[:TITLE] [FILE[:TITLE] ...]
                              [--window X0 X1 Y0 Y1] [-o OUT.png]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402


def read(path):
    with open(path) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    if not rows:
        sys.exit("plot_contact_points.py: %s has no contact points" % path)
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("files", nargs="+", help="contact_points-NN.csv[:title]")
    p.add_argument("--window", nargs=4, type=float, metavar=("X0", "X1", "Y0", "Y1"),
                   help="region to draw (default: all points)")
    p.add_argument("-o", "--output", default="contact_points.png")
    a = p.parse_args()

    fig, axes = plt.subplots(1, len(a.files), figsize=(5.2 * len(a.files), 5.6),
                             squeeze=False)
    for ax, spec in zip(axes[0], a.files):
        path, _, title = spec.partition(":")
        rows = read(path)
        nodes = {}
        for r in rows:
            key = (round(r["x"], 9), round(r["y"], 9))
            n = nodes.setdefault(key, [0, 0])
            n[0] += 1
            n[1] += r["status"] > 0
        lifted = sum(1 for r in rows if r["status"] == 0 and 0. < r["gap"] < 1e-6)
        active = sum(1 for r in rows if r["status"] > 0)
        xs, ys, colours = [], [], []
        for (x, y), (total, act) in nodes.items():
            if a.window and not (a.window[0] <= x <= a.window[1] and
                                 a.window[2] <= y <= a.window[3]):
                continue
            xs.append(x)
            ys.append(y)
            colours.append("#c0392b" if act == total else "#f39c12" if act else "#d5d8dc")
        size = 8e3 / max(len(xs), 1) ** 1.0
        ax.scatter(xs, ys, c=colours, s=max(2., min(size, 30.)), marker="s", linewidths=0)
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_title((title + "\n" if title else "") +
                     "%d points, %d active, %d lifted by < 1e-6" % (len(rows), active, lifted),
                     fontsize=10)
    fig.legend(handles=[Patch(color="#c0392b", label="active (every point at the node)"),
                        Patch(color="#f39c12", label="active in some of the cells at the node"),
                        Patch(color="#d5d8dc", label="inactive")],
               loc="lower center", ncol=3, fontsize=9)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    fig.savefig(a.output, dpi=80)
    print("wrote " + a.output)


if __name__ == "__main__":
    main()
