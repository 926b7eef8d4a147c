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

With --against FINAL.csv each panel shows instead where the status of
its file differs from that of FINAL (typically the iterates
contact_points-NN-iKKK.csv of 'Output/Contact points per iteration'
against the converged contact_points-NN.csv of the same cycle): red, a
point active in the file but inactive in FINAL; blue, inactive but active
in FINAL; light grey, the points active in FINAL (active or inactive only:
a stick <-> slip switch is not drawn). The files must hold the same points
(the same mesh).

usage: plot_contact_points.py FILE[:TITLE] [FILE[:TITLE] ...]
                              [--window X0 X1 Y0 Y1] [--against FINAL.csv]
                              [-o OUT.png]
"""
import argparse
import csv
import os
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


def point_key(r):
    return (round(r["x"], 9), round(r["y"], 9), round(r["cell_x"], 9), round(r["cell_y"], 9))


def draw_against(ax, rows, final, window, title):
    """Panel of the points whose status differs from the one in final."""
    target = {}
    for r in final:
        target[point_key(r)] = r["status"] > 0
    if len(target) != len(rows) or any(point_key(r) not in target for r in rows):
        sys.exit("plot_contact_points.py: --against needs files of the same points "
                 "(the same mesh); %d and %d points" % (len(rows), len(final)))

    def inside(r):
        return not window or (window[0] <= r["x"] <= window[1] and
                              window[2] <= r["y"] <= window[3])
    grey = [r for r in final if r["status"] > 0 and inside(r)]
    red = [r for r in rows if r["status"] > 0 and not target[point_key(r)] and inside(r)]
    blue = [r for r in rows if r["status"] == 0 and target[point_key(r)] and inside(r)]
    size = max(1., min(4e3 / max(len(grey), 1), 20.))
    ax.scatter([r["x"] for r in grey], [r["y"] for r in grey], c="#d5d8dc", s=size,
               marker="s", linewidths=0)
    for group, colour in ((red, "#c0392b"), (blue, "#2e86c1")):
        ax.scatter([r["x"] for r in group], [r["y"] for r in group], c=colour,
                   s=max(2. * size, 1.), marker="s", linewidths=0)
    wrong = sum(1 for r in rows if (r["status"] > 0) != target[point_key(r)])
    ax.set_aspect("equal")
    if window:
        ax.set_xlim(window[0], window[1])
        ax.set_ylim(window[2], window[3])
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title((title + "\n" if title else "") +
                 "%d of %d points with another status" % (wrong, len(rows)), fontsize=10)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("files", nargs="+", help="contact_points-NN.csv[:title]")
    p.add_argument("--window", nargs=4, type=float, metavar=("X0", "X1", "Y0", "Y1"),
                   help="region to draw (default: all points)")
    p.add_argument("--against", metavar="FINAL.csv",
                   help="draw where each file's status differs from this file's")
    p.add_argument("-o", "--output", default="contact_points.png")
    a = p.parse_args()
    final = read(a.against) if a.against else None

    fig, axes = plt.subplots(1, len(a.files), figsize=(5.2 * len(a.files), 5.6),
                             squeeze=False)
    for ax, spec in zip(axes[0], a.files):
        path, _, title = spec.partition(":")
        rows = read(path)
        if final is not None:
            draw_against(ax, rows, final, a.window, title)
            continue
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
    if final is not None:
        handles = [Patch(color="#c0392b", label="active, inactive in %s" % os.path.basename(a.against)),
                   Patch(color="#2e86c1", label="inactive, active there"),
                   Patch(color="#d5d8dc", label="active there")]
    else:
        handles = [Patch(color="#c0392b", label="active (every point at the node)"),
                   Patch(color="#f39c12", label="active in some of the cells at the node"),
                   Patch(color="#d5d8dc", label="inactive")]
    fig.legend(handles=handles, loc="lower center", ncol=3, fontsize=9)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    fig.savefig(a.output, dpi=80)
    print("wrote " + a.output)


if __name__ == "__main__":
    main()
