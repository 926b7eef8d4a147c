#!/usr/bin/env python3
"""Thickness study: 3D elasticity versus Mindlin-Reissner versus
Kirchhoff-Love on the paper's geometry as t/a goes from 1e-1 to 1e-3.

  python3 parameters/thickness_study.py [--exe build/nitsche-contact]
                                        [--out results/thickness]
                                        [--timeout 180]

The clamped plate [0,10]^2 (a = 10), E = 2e5, nu = 0.3, rigid plane x3 = -1
below the lower face, frictionless, for t in {1, 0.3, 0.1, 0.03, 0.01}. The
load is scaled with t^3, q = -0.02 (t/0.01)^3, so that q/D is the same for
every thickness, and the obstacle is moved with the lower face, Level =
-0.995 - t/2 (bottom-face convention), so that the mid-plane can always go
down to -0.995 (the paper's value, t = 0.01). With both, the Kirchhoff
problem for w is identical for every t, and the differences between the
models are the thickness effects (shear, 3D stresses) plus discretisation.
(With the plane kept at -1 the mid-plane could only reach -1 + t/2 = -0.5
at t = 1: a different contact problem for each thickness.)

Each run's .prm is parameters/paper_{3d,mindlin,mindlin_mitc9,kirchhoff}.prm with override
subsections appended (later entries override earlier ones in deal.II's
ParameterHandler):
  3D        Q2, Subdivisions 8,8,1 (8,8,2 for t >= 0.3), 2 cycles
            (last mesh 16x16x2, resp. 16x16x4)
  Mindlin   MITC4, 8x8, 4 nested cycles (last mesh 64x64)
  Mindlin   MITC9, 4x4, 4 nested cycles (last mesh 32x32, the same nodes)
  Kirchhoff BFS + GSV, 16x16, 3 nested cycles (last mesh 64x64)
Contact parameters (theta, gamma0, alpha) are those of the paper_*.prm files.
A 3D run that exceeds --timeout seconds is dropped (reported in the table).

Writes into --out: thickness.md, thickness.csv, thickness.png, and each
run's .prm, .log and output directory.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import time

from compare_models import pinned_settings

A = 10.0
THICKNESSES = [1.0, 0.3, 0.1, 0.03, 0.01]
PROBES = [(5.0, 5.0), (2.5, 5.0), (1.0, 5.0)]
MODELS = [
    ("3d", "3D Q2", "paper_3d.prm"),
    ("mindlin", "Mindlin MITC4", "paper_mindlin.prm"),
    ("mindlin9", "Mindlin MITC9", "paper_mindlin_mitc9.prm"),
    ("kirchhoff", "Kirchhoff GSV", "paper_kirchhoff.prm"),
]


def load(t):
    return -0.02 * (t / 0.01) ** 3


def obstacle(t):
    """Level of the plane below the lower face: the mid-plane gap is 0.995."""
    return -(1.0 - 0.005) - t / 2


def overrides(model, t, outdir):
    text = "\n# ---- thickness study overrides ----\n"
    text += "subsection Geometry\n  set Thickness = %.12g\n" % t
    if model == "3d":
        text += "  set Subdivisions = 8, 8, %d\n" % (2 if t >= 0.3 else 1)
        text += "  set Number of cycles = 2\n"
    elif model == "mindlin":
        text += "  set Subdivisions = 8, 8\n  set Number of cycles = 4\n"
    elif model == "mindlin9":
        # the same nodes as MITC4
        text += "  set Subdivisions = 4, 4\n  set Number of cycles = 4\n"
    else:
        text += "  set Subdivisions = 16, 16\n  set Number of cycles = 3\n"
    text += "end\n"
    if model == "3d":
        # refine through the thickness too, as when doc/thickness.md was
        # measured (thick plates need the layers; paper_3d.prm refines in
        # plane only)
        text += "subsection Elasticity\n  set Refine through thickness = true\nend\n"
    # the mid-plane rests at -0.995 for every t (the paper's value at t = 0.01)
    text += "subsection Obstacle\n  set Level = %.12g\nend\n" % obstacle(t)
    text += "subsection Load\n  set Transverse load = %.12g\nend\n" % load(t)
    text += "subsection Output\n  set Directory = %s\n" % outdir
    text += "  set Probe points = %s\n" % "; ".join("%g, %g" % p for p in PROBES)
    text += "  set Print timings = true\nend\n"
    return text


def run(exe, here, out, model, prm, t, timeout):
    name = "%s_t%g" % (model, t)
    outdir = os.path.abspath(os.path.join(out, name))
    # the discretisation the tests pin (rigid obstacle, Gauss contact points)
    text = (open(os.path.join(here, prm)).read() + pinned_settings(prm)
            + overrides(model, t, outdir))
    prm_out = os.path.join(out, name + ".prm")
    with open(prm_out, "w") as f:
        f.write(text)
    print("== %s, t = %g: %s %s" % (model, t, exe, prm_out), flush=True)
    t0 = time.time()
    status = "ok"
    with open(os.path.join(out, name + ".log"), "w") as log:
        try:
            proc = subprocess.run([exe, prm_out], stdout=log, stderr=subprocess.STDOUT,
                                  timeout=timeout)
            if proc.returncode != 0:
                status = "failed (exit %d)" % proc.returncode
        except subprocess.TimeoutExpired:
            status = "dropped (> %g s)" % timeout
    seconds = time.time() - t0
    if status != "ok":
        print("   %s, see %s.log" % (status, os.path.join(out, name)), flush=True)
        return dict(status=status, seconds=seconds)
    s = json.load(open(os.path.join(outdir, "summary.json")))
    last = s["cycles"][-1]
    r = dict(status=status, seconds=seconds, probes=last["probes"],
             force=last["contact_force"],
             reaction=last["contact_force"] / (abs(load(t)) * A * A),
             iterations=sum(c["nonlinear_iterations"] for c in s["cycles"]),
             dofs=last["n_dofs"])
    print("   w(5,5) = %.6g, w(1,5) = %.6g, reaction/(|q|a^2) = %.5g, %d its, %.1f s"
          % (r["probes"][0], r["probes"][2], r["reaction"], r["iterations"], seconds),
          flush=True)
    return r


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(here, "..", "build", "nitsche-contact"))
    ap.add_argument("--out", default="results/thickness")
    ap.add_argument("--timeout", type=float, default=180.0,
                    help="drop a run that takes longer (seconds)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    res = {}
    for t in THICKNESSES:
        for model, _, prm in MODELS:
            res[(model, t)] = run(args.exe, here, args.out, model, prm, t, args.timeout)

    write_tables(res, args.out)
    try:
        plot(res, args.out)
    except ImportError:
        print("matplotlib not available: no figure")
    return 0 if all(r["status"] == "ok" or r["status"].startswith("dropped")
                    for r in res.values()) else 1


def rel(a, b):
    return abs(a - b) / abs(b)


def write_tables(res, out):
    head = ["t/a", "q"]
    for _, label, _ in MODELS:
        head += ["%s %s" % (label, c) for c in
                 ["w(5,5)", "w(2.5,5)", "w(1,5)", "R/(|q|a^2)", "its", "time [s]"]]
    rows = []
    for t in THICKNESSES:
        row = ["%g" % (t / A), "%.6g" % load(t)]
        for model, _, _ in MODELS:
            r = res[(model, t)]
            if r["status"] == "ok":
                row += ["%.5f" % v for v in r["probes"]]
                row += ["%.5f" % r["reaction"], str(r["iterations"]), "%.1f" % r["seconds"]]
            else:
                row += [r["status"]] + ["-"] * 4 + ["%.1f" % r["seconds"]]
        rows.append(row)
    with open(os.path.join(out, "thickness.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(head)
        w.writerows(rows)

    # markdown: one table per quantity group keeps it readable
    lines = []
    lines.append("| t/a | q | model | w(5,5) | w(2.5,5) | w(1,5) | R/(\\|q\\|a²) | its | time [s] |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    for row in rows:
        for i, (_, label, _) in enumerate(MODELS):
            cells = row[2 + 6 * i: 8 + 6 * i]
            lines.append("| %s | %s | %s | %s |" % (row[0], row[1], label, " | ".join(cells)))
    lines.append("")
    lines.append("Relative differences with respect to Kirchhoff:")
    lines.append("")
    lines.append("| t/a | 3D w(1,5) | MITC4 w(1,5) | MITC9 w(1,5) | 3D reaction "
                 "| MITC4 reaction | MITC9 reaction | 3D w(2.5,5) | MITC4 w(2.5,5) "
                 "| MITC9 w(2.5,5) |")
    lines.append("|---|---|---|---|---|---|---|---|---|---|")
    for t in THICKNESSES:
        k = res[("kirchhoff", t)]
        cells = ["%g" % (t / A)]
        for what in [("probes", 2), ("reaction", None), ("probes", 1)]:
            for model in ["3d", "mindlin", "mindlin9"]:
                r = res[(model, t)]
                if r["status"] != "ok" or k["status"] != "ok":
                    cells.append("-")
                    continue
                if what[1] is None:
                    cells.append("%.2e" % rel(r["reaction"], k["reaction"]))
                else:
                    cells.append("%.2e" % rel(r["probes"][what[1]], k["probes"][what[1]]))
        lines.append("| " + " | ".join(cells) + " |")
    dropped = [(m, t) for (m, t), r in res.items() if r["status"] != "ok"]
    if dropped:
        lines.append("")
        for m, t in dropped:
            lines.append("- %s at t = %g: %s" % (m, t, res[(m, t)]["status"]))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "thickness.md"), "w") as f:
        f.write(text)
    print(text)


def plot(res, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, (title, get) in zip(axes, [
            ("w(1,5)", lambda r: r["probes"][2]),
            ("reaction", lambda r: r["reaction"])]):
        for model, label, mk in [("3d", "3D Q2 vs Kirchhoff", "o-"),
                                 ("mindlin", "Mindlin MITC4 vs Kirchhoff", "s-"),
                                 ("mindlin9", "Mindlin MITC9 vs Kirchhoff", "^-")]:
            x, y = [], []
            for t in THICKNESSES:
                r, k = res[(model, t)], res[("kirchhoff", t)]
                if r["status"] == "ok" and k["status"] == "ok":
                    x.append(t / A)
                    y.append(max(rel(get(r), get(k)), 1e-12))
            ax.loglog(x, y, mk, label=label)
        xs = [t / A for t in THICKNESSES]
        ax.loglog(xs, [2.0 * (s / 0.1) ** 2 * 1e-1 for s in xs], "k:", lw=0.8,
                  label="slope 2, (t/a)²")
        ax.set_xlabel("t/a")
        ax.set_ylabel("relative difference")
        ax.set_title("%s: relative difference to Kirchhoff" % title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "thickness.png"), dpi=120)


if __name__ == "__main__":
    sys.exit(main())
