#!/usr/bin/env python3
"""The main job: the paper's test (Fabre, Pozzolini, Renard 2019, section 4)
solved with every model and contact formulation, then one comparison table
and the figures.

  python3 parameters/compare_models.py [--exe build/nitsche-contact]
                                       [--out results/comparison] [--quick]
                                       [--compliance VALUE] [--more-cycles N]
                                       [--pinned]

Runs parameters/{paper_3d, paper_mindlin, paper_mindlin_mitc9,
paper_kirchhoff, kirchhoff_nitsche}.prm, the two Mindlin files also with
'Contact formulation = gsv', with a common output block (same probes,
profile line and field grid), reads each summary.json, profile.csv and field.csv, and
writes into --out:
  comparison.md, comparison.csv   probe deflections, contact area, total
                                  reaction, min/max deflection, DoFs,
                                  iterations, wall time (last cycle)
  profiles.png                    centre-line deflection of all models
  fields.png                      each model's deflection field with the
                                  region where the plate lies on the
                                  obstacle (paper's Figures 1-3)
  differences.png                 each model's centre-line deflection
                                  minus the Kirchhoff GSV plate's
  convergence.png                 the reaction of every cycle against
                                  its DoFs
  pressure.png                    the contact pressure along y = 5 (the
                                  pressure column of profile.csv)
  status.png                      the contact status of every contact
                                  point of the last cycle
  surface.png                     the Mindlin plate's deflection as a
                                  warped surface
--pinned solves the discretisation most tests pin (tests/verification/
common.py): the rigid obstacle, Gauss contact points (3D: 3x3 with
gamma0 = 20 and the nested start; MITC4: 4x4) instead of the defaults.
--quick uses one coarse cycle per model (for tests). --compliance sets
'Contact/Obstacle compliance' in every run (e.g. 0 for the rigid obstacle;
by default each file's own, 'auto' unless it says otherwise). --more-cycles
N refines every run N more times than its file (the next finer meshes).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

# (key, label, parameter file, entries appended to it): the Mindlin plate
# with the paper's contact stress and with the plate's equilibrium stress
# ('Contact formulation = gsv' and its gamma0 = auto, doc/mindlin.md)
GSV = ("subsection Mindlin\n  set Contact formulation = gsv\nend\n"
       "subsection Contact\n  set Nitsche gamma0 = auto\nend\n")
RUNS = [
    ("elasticity", "3D elasticity, Q2, Nitsche", "paper_3d.prm", ""),
    ("mindlin", "Mindlin-Reissner, MITC4, Nitsche", "paper_mindlin.prm", ""),
    ("mindlin_gsv", "Mindlin-Reissner, MITC4, GSV", "paper_mindlin.prm", GSV),
    ("mindlin_mitc9", "Mindlin-Reissner, MITC9, Nitsche", "paper_mindlin_mitc9.prm", ""),
    ("mindlin_mitc9_gsv", "Mindlin-Reissner, MITC9, GSV", "paper_mindlin_mitc9.prm", GSV),
    ("kirchhoff_gsv", "Kirchhoff-Love, BFS, GSV", "paper_kirchhoff.prm", ""),
    ("kirchhoff_nitsche", "Kirchhoff-Love, BFS, Nitsche", "kirchhoff_nitsche.prm", ""),
]
def pinned_settings(prm_file):
    """The entries that turn a shipped paper file into the discretisation
    most tests pin (tests/verification/common.py): the rigid obstacle, and
    Gauss contact points (3D: with gamma0 = 20 and the nested start; MITC4:
    4x4). Appended after the file, they win; the studies use them too."""
    text = "subsection Contact\n  set Obstacle compliance = 0\nend\n"
    if prm_file.startswith("paper_3d"):
        text += ("subsection Contact\n  set Nitsche gamma0 = 20\nend\n"
                 "subsection Elasticity\n  set Contact quadrature rule = gauss\n"
                 "  set Plate predictor = false\nend\n")
    if prm_file in ("paper_mindlin.prm", "paper_mindlin_friction.prm"):
        text += "subsection Mindlin\n  set Contact quadrature rule = gauss\nend\n"
    return text
PROBES = [(5.0, 5.0), (2.5, 5.0), (1.0, 5.0), (2.5, 2.5)]
OBSTACLE = -1.0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(here, "..", "build", "nitsche-contact"))
    ap.add_argument("--out", default="results/comparison")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--np", type=int, default=1, help="MPI ranks for the 3D model")
    ap.add_argument("--compliance", default=None,
                    help="'Contact/Obstacle compliance' of every run")
    ap.add_argument("--more-cycles", type=int, default=0,
                    help="refinement cycles added to each file's")
    ap.add_argument("--pinned", action="store_true",
                    help="the rigid Gauss discretisation the tests pin")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    rows = []
    for key, label, prm, entries in RUNS:
        text = open(os.path.join(here, prm)).read() + entries
        outdir = os.path.abspath(os.path.join(args.out, key))
        text += "\nsubsection Output\n  set Directory = %s\n" % outdir
        text += "  set Probe points = %s\n" % "; ".join("%g, %g" % p for p in PROBES)
        text += "  set Profile line = 0, 5; 10, 5\n  set Profile points = 201\n"
        text += "  set Field grid points = 81\n  set Print timings = true\n"
        text += "  set Contact points = true\nend\n"
        if args.quick:
            text += "subsection Geometry\n  set Number of cycles = 1\nend\n"
        elif args.more_cycles > 0:
            cycles = [l for l in text.splitlines()
                      if l.strip().startswith("set Number of cycles")]
            n = int(cycles[-1].split("=")[1]) + args.more_cycles
            text += "subsection Geometry\n  set Number of cycles = %d\nend\n" % n
        if args.pinned:
            text += pinned_settings(prm)
        if args.compliance is not None:
            text += "subsection Contact\n  set Obstacle compliance = %s\nend\n" % args.compliance
        prm_out = os.path.join(args.out, key + ".prm")
        with open(prm_out, "w") as f:
            f.write(text)
        cmd = [args.exe, prm_out]
        if key == "elasticity" and args.np > 1:
            cmd = ["mpirun", "-np", str(args.np)] + cmd
        print("== %s: %s" % (label, " ".join(cmd)), flush=True)
        t0 = time.time()
        with open(os.path.join(args.out, key + ".log"), "w") as log:
            proc = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT)
        seconds = time.time() - t0
        if proc.returncode != 0:
            print("   FAILED (exit status %d), see %s.log" % (proc.returncode,
                                                            os.path.join(args.out, key)))
            continue
        s = json.load(open(os.path.join(outdir, "summary.json")))
        last = s["cycles"][-1]
        rows.append(dict(key=key, model=label, dofs=last["n_dofs"],
                         iterations=sum(c["nonlinear_iterations"] for c in s["cycles"]),
                         last_iterations=last["nonlinear_iterations"],
                         area=last["contact_area"], force=last["contact_force"],
                         wmin=last["min_deflection"], wmax=last["max_deflection"],
                         probes=last["probes"], seconds=seconds, outdir=outdir))
        print("   %d DoFs, w(5,5) = %.6g, contact area %.4g, reaction %.4g, %.1f s"
              % (last["n_dofs"], last["probes"][0], last["contact_area"],
                 last["contact_force"], seconds), flush=True)

    write_table(rows, args.out)
    try:
        plot(rows, args.out)
    except ImportError:
        print("matplotlib not available: no figures")
    return 0 if len(rows) == len(RUNS) else 1


def write_table(rows, out):
    head = (["model", "DoFs", "its (all cycles)", "its (last)"]
            + ["w(%g,%g)" % p for p in PROBES]
            + ["contact area", "reaction", "min w", "max w", "time [s]"])
    with open(os.path.join(out, "comparison.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(head)
        for r in rows:
            w.writerow([r["model"], r["dofs"], r["iterations"], r["last_iterations"]]
                       + ["%.6g" % v for v in r["probes"]]
                       + ["%.6g" % r["area"], "%.6g" % r["force"], "%.6g" % r["wmin"],
                          "%.6g" % r["wmax"], "%.1f" % r["seconds"]])
    with open(os.path.join(out, "comparison.md"), "w") as f:
        f.write("| " + " | ".join(head) + " |\n")
        f.write("|" + "---|" * len(head) + "\n")
        for r in rows:
            cells = ([r["model"], str(r["dofs"]), str(r["iterations"]), str(r["last_iterations"])]
                     + ["%.5f" % v for v in r["probes"]]
                     + ["%.4f" % r["area"], "%.5f" % r["force"], "%.5f" % r["wmin"],
                        "%.3g" % r["wmax"], "%.1f" % r["seconds"]])
            f.write("| " + " | ".join(cells) + " |\n")
    print(open(os.path.join(out, "comparison.md")).read())


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    for r in rows:
        data = list(csv.DictReader(open(os.path.join(r["outdir"], "profile.csv"))))
        ax.plot([float(d["x"]) for d in data], [float(d["deflection"]) for d in data],
                label=r["model"])
    ax.axhline(OBSTACLE, color="k", lw=0.8, ls="--", label="obstacle x3 = -1")
    ax.set_xlabel("x (y = 5)")
    ax.set_ylabel("deflection of the mid-plane")
    ax.set_title("Paper test: centre-line deflection")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles.png"), dpi=130)

    n = len(rows)
    fig, axes = plt.subplots(1, n, figsize=(4 * n, 3.8), squeeze=False)
    for ax, r in zip(axes[0], rows):
        X, Y, W = read_field(r["outdir"])
        cs = ax.contourf(X, Y, W, levels=20, cmap="viridis")
        # plate on the obstacle: mid-plane within 1e-3 of its lowest level
        lowest = OBSTACLE + 0.005
        ax.contour(X, Y, W, levels=[lowest + 1e-3], colors="r", linewidths=1.2)
        ax.set_title(r["model"], fontsize=9)
        ax.set_aspect("equal")
        fig.colorbar(cs, ax=ax, shrink=0.8)
    fig.suptitle("Deflection; red: boundary of the region within 1e-3 of the obstacle")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fields.png"), dpi=110)
    plot_differences(rows, out, plt)
    plot_convergence(rows, out, plt)
    plot_pressure(rows, out, plt)
    plot_status(rows, out, plt)
    plot_surface(rows, out, plt)


def read_field(outdir):
    """The square grid of field.csv as lists of rows X, Y, W."""
    data = list(csv.DictReader(open(os.path.join(outdir, "field.csv"))))
    m = int(round(len(data) ** 0.5))
    return tuple([[float(data[j * m + i][key]) for i in range(m)] for j in range(m)]
                 for key in ("x", "y", "deflection"))


def plot_surface(rows, out, plt):
    """surface.png: the Mindlin plate's deflection from field.csv as a
    surface warped by the deflection, the view that ParaView's 'Warp By
    Scalar' gives (doc/outputs.md)."""
    r = [r for r in rows if r["key"] == "mindlin"]
    if not r:
        return
    X, Y, W = read_field(r[0]["outdir"])
    fig = plt.figure(figsize=(6, 4.5))
    ax = fig.add_subplot(projection="3d")
    import numpy as np
    surf = ax.plot_surface(np.array(X), np.array(Y), np.array(W), cmap="viridis",
                           linewidth=0, antialiased=True)
    ax.set_box_aspect((1, 1, 0.35))
    ax.view_init(elev=25, azim=-60)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zticks([0., -0.5, -1.])
    ax.set_zlabel("w")
    fig.colorbar(surf, shrink=0.6, label="deflection w")
    ax.set_title(r[0]["model"] + ": deflection, warped", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "surface.png"), dpi=110)


def last_contact_points(r):
    """The rows of the last cycle's contact_points-NN.csv of a run."""
    files = sorted(f for f in os.listdir(r["outdir"])
                   if f.startswith("contact_points-") and f.count("-") == 1)
    return list(csv.DictReader(open(os.path.join(r["outdir"], files[-1])))) if files else []


def plot_status(rows, out, plt):
    """status.png: the contact status of every contact point of the last
    cycle (grey: no contact, blue: contact), one panel per model."""
    n = len(rows)
    fig, axes = plt.subplots(1, n, figsize=(4 * n, 4), squeeze=False)
    for ax, r in zip(axes[0], rows):
        points = last_contact_points(r)
        # each point a square of its quadrature weight (the panels are
        # about 260 points wide for the 10 units of the plate)
        scale = (260. / 10.) ** 2
        for active, colour in ((False, "0.85"), (True, "tab:blue")):
            sel = [p for p in points if (int(p["status"]) > 0) == active]
            ax.scatter([float(p["x"]) for p in sel], [float(p["y"]) for p in sel],
                       s=[scale * float(p["weight"]) for p in sel], c=colour,
                       marker="s", linewidths=0)
        ax.set_title(r["model"], fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlim(0, 10)
        ax.set_ylim(0, 10)
    fig.suptitle("Contact status of the contact points (blue: in contact)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "status.png"), dpi=110)


def plot_pressure(rows, out, plt):
    """pressure.png: the contact pressure along the centre line from
    profile.csv, the mean over the contact points of the cell (3D: of the
    contact face) that holds each point."""
    fig, ax = plt.subplots(figsize=(7, 4))
    for r in rows:
        data = list(csv.DictReader(open(os.path.join(r["outdir"], "profile.csv"))))
        ax.plot([float(d["x"]) for d in data], [float(d["pressure"]) for d in data],
                label=r["model"], lw=1)
    ax.axhline(0.02, color="k", lw=0.8, ls="--", label="the load |q| = 0.02")
    ax.set_xlabel("x on the centre line y = 5")
    ax.set_ylabel("contact pressure (cell mean)")
    ax.set_title("Paper test: contact pressure")
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pressure.png"), dpi=130)


def plot_differences(rows, out, plt):
    """differences.png: each model's centre-line deflection minus the
    Kirchhoff GSV plate's, where the overlapping curves of profiles.png
    differ."""
    ref = [r for r in rows if r["key"] == "kirchhoff_gsv"]
    if not ref:
        return
    w_ref = [float(d["deflection"]) for d in
             csv.DictReader(open(os.path.join(ref[0]["outdir"], "profile.csv")))]
    fig, ax = plt.subplots(figsize=(7, 4))
    for r in rows:
        if r is ref[0]:
            continue
        data = list(csv.DictReader(open(os.path.join(r["outdir"], "profile.csv"))))
        ax.plot([float(d["x"]) for d in data],
                [float(d["deflection"]) - w for d, w in zip(data, w_ref)], label=r["model"])
    ax.axhline(0., color="k", lw=0.8)
    ax.set_xlabel("x (y = 5)")
    ax.set_ylabel("deflection minus Kirchhoff GSV")
    ax.set_title("Paper test: difference to the Kirchhoff GSV plate")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "differences.png"), dpi=130)


def plot_convergence(rows, out, plt):
    """convergence.png: the reaction of every cycle against its DoFs, per
    model."""
    fig, ax = plt.subplots(figsize=(7, 4))
    for r in rows:
        cycles = json.load(open(os.path.join(r["outdir"], "summary.json")))["cycles"]
        ax.semilogx([c["n_dofs"] for c in cycles], [c["contact_force"] for c in cycles],
                    "o-", label=r["model"])
    ax.set_xlabel("DoFs")
    ax.set_ylabel("reaction of the obstacle")
    ax.set_title("Paper test: reaction on each cycle")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "convergence.png"), dpi=130)


if __name__ == "__main__":
    sys.exit(main())
