#!/usr/bin/env python3
"""Convergence and parameter study on the paper's test.

  /usr/bin/python3 parameters/convergence_study.py build/nitsche-contact results/convergence
                   [--parts abcd] [--quick]

Runs the program (one instance at a time) on the paper's test (Fabre,
Pozzolini, Renard 2019, section 4: clamped [0,10]^2, t = 0.01, E = 2e5,
nu = 0.3, q = -0.02, rigid plane x3 = -1) and writes each table as
<out>/<table>.txt (aligned columns), .tex (tabular) and .csv, plus all of
them in <out>/tables.md. Every run's .prm and output are kept in
<out>/runs/<name>/ (and <name>.log).

Parts (--parts selects, default all):
  a  Kirchhoff GSV: theta in {1, 0, -1} x alpha*D in {1e-6 ... 1e-2} on a
     32x32 mesh (cold start, one cycle), and the pure penalty method
     (alpha = 0) with compliance kappa -> 0; differences from the 256x256
     reference of part d (GSV, theta = 1, alpha*D = 1e-4) and from the same
     mesh with the default parameters. Tables kirchhoff_theta_alpha,
     kirchhoff_kappa.
  b  3D model, theta x gamma0: runs tests/verification/elasticity_theta_gamma.py
     (Hertz block, Q1, 3318 DoFs; the thin plate in 3D is too expensive for
     a 15-run sweep) and tabulates its runs. Table elasticity_theta_gamma.
  c  fixed point versus Newton: iterations of both schemes for every model
     and contact formulation on coarse/moderate meshes of the paper's test
     (3D on 8x8x1 Q2 only), frictionless (where the two schemes coincide by
     construction), plus the Mindlin plate with Coulomb friction F = 0.2
     (where they differ). Table fixed_point_newton.
  d  EOC against a fine-mesh reference: Kirchhoff GSV 16^2 -> 128^2 and
     Mindlin MITC4 16^2 -> 128^2 (parameters of paper_kirchhoff.prm and
     paper_mindlin.prm), nested iteration, the 256^2 cycle of the same run
     is the reference. Tables eoc_kirchhoff_gsv, eoc_mindlin.
--quick: smaller meshes and fewer runs (a smoke test of the script only;
the tables in doc/convergence.md are from the full run).

Non-convergence is reported, not hidden: a run that stops with exit
status 2 appears as "no" with the iteration limit it reached.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time

from compare_models import pinned_settings

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PROBES = [(5.0, 5.0), (2.5, 5.0), (1.0, 5.0), (2.5, 2.5)]
PROBE_TEXT = "; ".join("%g, %g" % p for p in PROBES)

args = None
tables_md = []


# --------------------------------------------------------------------------
# running the program

def paper_prm(prm_file, **over):
    """Text of parameters/<prm_file> in the discretisation the tests pin
    (compare_models.pinned_settings: the rigid obstacle, Gauss contact
    points), with overrides appended (later entries win in deal.II's
    ParameterHandler). over: dict subsection -> {entry: value}; the key ''
    is the top level."""
    text = open(os.path.join(HERE, prm_file)).read() + pinned_settings(prm_file)
    return text + overrides(**over)


def overrides(**over):
    text = "\n"
    for sec, entries in over.items():
        if sec == "":
            for k, v in entries.items():
                text += "set %s = %s\n" % (k, v)
            continue
        text += "subsection %s\n" % sec.replace("_", " ")
        for k, v in entries.items():
            text += "  set %s = %s\n" % (k, v)
        text += "end\n"
    return text


def run(name, prm_text):
    """Run the program on prm_text; return dict(status, seconds, summary,
    cycles) where cycles is the list of per-cycle records (possibly with a
    non-converged last cycle)."""
    rundir = os.path.join(args.out, "runs")
    os.makedirs(rundir, exist_ok=True)
    outdir = os.path.join(rundir, name)
    prm_file = os.path.join(rundir, name + ".prm")
    with open(prm_file, "w") as f:
        f.write(prm_text)
        f.write(overrides(Output={"Directory": outdir, "Format": "none",
                                  "Probe points": PROBE_TEXT}))
    summary_file = os.path.join(outdir, "summary.json")
    if os.path.exists(summary_file):
        os.remove(summary_file)
    t0 = time.time()
    with open(os.path.join(rundir, name + ".log"), "w") as log:
        proc = subprocess.run([args.exe, prm_file], stdout=log, stderr=subprocess.STDOUT)
    seconds = time.time() - t0
    if proc.returncode not in (0, 2):
        sys.exit("convergence_study: run %s failed with exit status %d, see %s.log"
                 % (name, proc.returncode, os.path.join(rundir, name)))
    summary = json.load(open(summary_file)) if os.path.exists(summary_file) else None
    cycles = summary["cycles"] if summary else []
    last = cycles[-1] if cycles else None
    print("  %-40s status %d  %6.1f s  %s" % (
        name, proc.returncode, seconds,
        ("its %d, reaction %.6g" % (last["nonlinear_iterations"], last["contact_force"]))
        if last and last.get("converged") and "contact_force" in last else "not converged"),
        flush=True)
    return dict(status=proc.returncode, seconds=seconds, summary=summary, cycles=cycles)


def converged(c):
    return c is not None and c.get("converged", False) and "contact_force" in c


# --------------------------------------------------------------------------
# tables

def fmt(v, f="%.6g"):
    if v is None:
        return "-"
    if isinstance(v, str):
        return v
    if isinstance(v, float) and math.isnan(v):
        return "-"
    return f % v


def write_table(name, title, header, rows, notes=""):
    """rows: lists of strings (already formatted)."""
    path = os.path.join(args.out, name)
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h)
              for i, h in enumerate(header)]
    with open(path + ".txt", "w") as f:
        f.write("# " + title + "\n")
        f.write("  ".join(h.rjust(w) for h, w in zip(header, widths)) + "\n")
        for r in rows:
            f.write("  ".join(c.rjust(w) for c, w in zip(r, widths)) + "\n")
    with open(path + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)

    def tex(s):
        for a, b in (("\\", "\\textbackslash{}"), ("%", "\\%"), ("_", "\\_"),
                     ("&", "\\&"), ("#", "\\#"), ("^", "\\^{}"),
                     ("|", "$|$"), ("₊", "$_+$"), ("→", "$\\to$"),
                     ("θ", "$\\theta$"), ("α", "$\\alpha$"), ("γ", "$\\gamma$"),
                     ("κ", "$\\kappa$"), ("·", "$\\cdot$"), ("Δ", "$\\Delta$"),
                     ("²", "$^2$"), ("−", "$-$")):
            s = s.replace(a, b)
        return s
    with open(path + ".tex", "w") as f:
        f.write("%% %s\n\\begin{tabular}{%s}\n\\hline\n" % (tex(title), "r" * len(header)))
        f.write(" & ".join(tex(h) for h in header) + " \\\\\n\\hline\n")
        for r in rows:
            f.write(" & ".join(tex(c) for c in r) + " \\\\\n")
        f.write("\\hline\n\\end{tabular}\n")
    md = "### %s\n\n" % title
    if notes:
        md += notes.strip() + "\n\n"
    md += "```\n" + open(path + ".txt").read().split("\n", 1)[1] + "```\n"
    tables_md.append(md)
    print("\n" + open(path + ".txt").read(), flush=True)


def rel(a, b):
    if a is None or b is None:
        return None
    return (a - b) / abs(b)


# --------------------------------------------------------------------------
# part d: EOC against a fine-mesh reference (run first: part a uses the
# GSV reference)

EOC_RUNS = {
    "kirchhoff_gsv": ("paper_kirchhoff.prm", "Kirchhoff GSV, BFS, θ=1, α·D=1e-4"),
    "mindlin": ("paper_mindlin.prm", "Mindlin, MITC4, Nitsche θ=1, γ0=200"),
}


def eoc_run(key):
    prm, _ = EOC_RUNS[key]
    n0, cycles = (8, 3) if args.quick else (16, 5)
    return run("eoc_" + key, paper_prm(prm, Geometry={"Subdivisions": "%d, %d" % (n0, n0),
                                                      "Number of cycles": cycles}))


def part_d(results):
    for key in EOC_RUNS:
        r = results.get("eoc_" + key) or eoc_run(key)
        results["eoc_" + key] = r
        cyc = r["cycles"]
        if not cyc or not all(converged(c) for c in cyc):
            write_table("eoc_" + key, EOC_RUNS[key][1] + ": NOT CONVERGED",
                        ["cycle"], [[str(len(cyc))]])
            continue
        ref = cyc[-1]
        quantities = [("reaction", lambda c: c["contact_force"]),
                      ("w(2.5,5)", lambda c: c["probes"][1]),
                      ("w(1,5)", lambda c: c["probes"][2]),
                      ("w(2.5,2.5)", lambda c: c["probes"][3]),
                      ("area", lambda c: c["contact_area"])]
        header = ["cells", "DoFs", "its"]
        for q, _ in quantities:
            header += [q, "err", "EOC"]
        rows = []
        prev = None
        curve_dofs, curve_errors = [], []
        for c in cyc[:-1]:
            n = int(round(10.0 / c["h"])) if c["h"] > 0 else 0
            row = ["%d²" % n, str(c["n_dofs"]), str(c["nonlinear_iterations"])]
            errs = []
            for i, (q, f) in enumerate(quantities):
                e = abs(f(c) - f(ref)) / abs(f(ref))
                errs.append(e)
                eoc = (math.log2(prev[i] / e) if prev and e > 0 and prev[i] > 0 else None)
                row += [fmt(f(c), "%.6f" if q != "area" else "%.4f"), fmt(e, "%.2e"),
                        fmt(eoc, "%.2f")]
            prev = errs
            rows.append(row)
            curve_dofs.append(c["n_dofs"])
            curve_errors.append(errs)
        n = int(round(10.0 / ref["h"]))
        rows.append(["%d² (ref)" % n, str(ref["n_dofs"]), str(ref["nonlinear_iterations"])]
                    + sum([[fmt(f(ref), "%.6f" if q != "area" else "%.4f"), "", ""]
                           for q, f in quantities], []))
        write_table("eoc_" + key,
                    "EOC vs the finest cycle, %s (nested iteration, %.0f s in all)"
                    % (EOC_RUNS[key][1], r["seconds"]), header, rows)
        plot_eoc("eoc_" + key, EOC_RUNS[key][1], curve_dofs,
                 [q for q, _ in quantities], curve_errors)


def plot_eoc(name, label, dofs, quantities, errors):
    """<name>.png: the relative errors against the finest cycle over the
    DoFs, log-log, one curve per quantity, with the slopes of h and h^2."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: no %s.png" % name)
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    for i, q in enumerate(quantities):
        pts = [(n, e[i]) for n, e in zip(dofs, errors) if e[i] > 0]
        if pts:
            ax.loglog([n for n, _ in pts], [e for _, e in pts], "o-", label=q)
    if len(dofs) > 1:
        top = max(max(e) for e in errors)
        for order, style in ((1, ":"), (2, "--")):
            # the error of h^order against the DoFs ~ h^-2
            ax.loglog([dofs[0], dofs[-1]],
                      [top, top * (dofs[0] / dofs[-1]) ** (order / 2.)],
                      "k" + style, lw=0.8, label="h^%d" % order)
    ax.set_xlabel("DoFs")
    ax.set_ylabel("relative error against the finest cycle")
    ax.set_title(label, fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, name + ".png"), dpi=120)
    plt.close(fig)


# --------------------------------------------------------------------------
# part a: Kirchhoff GSV theta x alpha, kappa limit

def part_a(results):
    n = 16 if args.quick else 32
    ref = results.get("eoc_kirchhoff_gsv")
    if ref is None:
        ref = results["eoc_kirchhoff_gsv"] = eoc_run("kirchhoff_gsv")
    fine = ref["cycles"][-1] if ref["cycles"] and converged(ref["cycles"][-1]) else None
    fine_n = int(round(10.0 / fine["h"])) if fine else 0

    def base(**over):
        # (the rigid obstacle: the tables compare discretisations of one problem)
        o = {"Geometry": {"Subdivisions": "%d, %d" % (n, n), "Number of cycles": 1},
             "Contact": {"Obstacle compliance": 0}}
        for k, v in over.items():
            o.setdefault(k, {}).update(v)
        return paper_prm("paper_kirchhoff.prm", **o)

    alphas = (1e-6, 1e-4, 1e-2) if args.quick else (1e-6, 1e-5, 1e-4, 1e-3, 1e-2)
    bound = {1: 1.89e-4, 0: 7.5e-4, -1: float("inf")}
    runs = {}
    for theta in (1, 0, -1):
        for a in alphas:
            runs[theta, a] = run("gsv_theta%+d_alpha%g" % (theta, a),
                                 base(Contact={"Nitsche theta": theta},
                                      Kirchhoff={"Stabilisation alpha": "%g" % a}))
    default = runs.get((1, 1e-4))
    d = default["cycles"][-1] if default and converged(default["cycles"][-1]) else None
    header = ["θ", "α·D", "coercive", "conv.", "its", "reaction", "w(2.5,5)", "w(1,5)",
              "area", "Δreact(def)", "Δw(1,5)(def)", "Δreact(ref)", "Δw(2.5,5)(ref)",
              "Δw(1,5)(ref)"]
    rows = []
    for (theta, a), r in runs.items():
        c = r["cycles"][-1] if r["cycles"] else None
        ok = converged(c)
        row = ["%+d" % theta, "%g" % a, "yes" if a < bound[theta] else "no",
               "yes" if ok else "no (exit %d)" % r["status"],
               str(c["nonlinear_iterations"]) if c else "-"]
        if ok:
            row += [fmt(c["contact_force"], "%.6f"), fmt(c["probes"][1], "%.6f"),
                    fmt(c["probes"][2], "%.6f"), fmt(c["contact_area"], "%.4f")]
            row += [fmt(rel(c["contact_force"], d["contact_force"]), "%+.1e") if d else "-",
                    fmt(rel(c["probes"][2], d["probes"][2]), "%+.1e") if d else "-"]
            row += ([fmt(rel(c["contact_force"], fine["contact_force"]), "%+.1e"),
                     fmt(rel(c["probes"][1], fine["probes"][1]), "%+.1e"),
                     fmt(rel(c["probes"][2], fine["probes"][2]), "%+.1e")]
                    if fine else ["-"] * 3)
        else:
            row += ["-"] * 9
        rows.append(row)
    write_table("kirchhoff_theta_alpha",
                "Kirchhoff GSV on %d² cells (cold start): θ × α·D; Δ(def) relative to θ=1, "
                "α·D=1e-4 on the same mesh, Δ(ref) relative to the %d² reference"
                % (n, fine_n), header, rows,
                notes="Coercivity bounds (parameter help of Kirchhoff/Stabilisation alpha, "
                      "ν = 0.3): θ = 1 needs α·D < 1.89e-4, θ = 0 needs α·D < 7.5e-4, "
                      "θ = −1 any α·D > 0.")

    # kappa limit: pure penalty (alpha = 0) p = [psi - w]_+ / kappa
    kappas = (1e-2, 1e-4, 1e-6) if args.quick else (1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7)
    rows = []
    prev = None
    for kappa in kappas:
        r = run("penalty_kappa%g" % kappa,
                base(Kirchhoff={"Stabilisation alpha": 0},
                     Contact={"Obstacle compliance": "%g" % kappa}))
        c = r["cycles"][-1] if r["cycles"] else None
        if not converged(c):
            rows.append(["%g" % kappa, "no (exit %d)" % r["status"]] + ["-"] * 9)
            continue

        def maxdiff(o):
            return max(abs(c["probes"][i] - o["probes"][i]) for i in range(4)) if o else None
        rows.append(["%g" % kappa, "yes", str(c["nonlinear_iterations"]),
                     fmt(c["contact_force"], "%.6f"), fmt(c["probes"][2], "%.6f"),
                     fmt(c["min_deflection"], "%.6f"),
                     fmt(maxdiff(prev), "%.2e"),
                     fmt(rel(c["contact_force"], d["contact_force"]) if d else None, "%+.2e"),
                     fmt(maxdiff(d), "%.2e"),
                     fmt(rel(c["contact_force"], fine["contact_force"]) if fine else None, "%+.2e"),
                     fmt(maxdiff(fine), "%.2e")])
        prev = c
    write_table("kirchhoff_kappa",
                "Kirchhoff, pure penalty (α = 0) with compliance κ on %d² cells" % n,
                ["κ", "conv.", "its", "reaction", "w(1,5)", "min w", "max|Δw| vs κ·10",
                 "Δreact (GSV)", "max|Δw| (GSV)", "Δreact (ref)", "max|Δw| (ref)"], rows,
                notes="Pure penalty p = [ψ − w]₊/κ (κ in length per pressure). 'vs κ·10': "
                      "largest change of the four probe deflections from the previous κ "
                      "(convergence in κ); (GSV): relative to GSV θ=1, α·D=1e-4 on the same "
                      "mesh; (ref): relative to the %d² GSV reference. min w below −0.995 is "
                      "the penetration κ·p allowed by the compliance." % fine_n)


# --------------------------------------------------------------------------
# part b: 3D theta x gamma0 (reuse the verification test's runs)

def part_b(results):
    test = os.path.join(ROOT, "tests", "verification", "elasticity_theta_gamma.py")
    workdir = os.path.join(args.out, "runs", "elasticity_theta_gamma")
    os.makedirs(workdir, exist_ok=True)
    t0 = time.time()
    with open(workdir + ".log", "w") as log:
        proc = subprocess.run([sys.executable, test, "--exe", args.exe, "--workdir", workdir],
                              stdout=log, stderr=subprocess.STDOUT)
    print("  elasticity_theta_gamma.py: exit status %d, %.1f s" % (proc.returncode,
                                                                  time.time() - t0))
    gammas = (0.01, 0.1, 1, 10, 100)
    bound = {-1: 0.0, 0: 0.25 * 2.21, 1: 2.21}

    def load(theta, g):
        f = os.path.join(workdir, "tg_theta%d_gamma%g" % (theta, g), "summary.json")
        return json.load(open(f))["cycles"][-1] if os.path.exists(f) else None
    ref = load(1, 100)
    rows = []
    for theta in (1, 0, -1):
        for g in gammas:
            c = load(theta, g)
            ok = converged(c)
            rows.append(["%+d" % theta, "%g" % g, "yes" if g > bound[theta] else "no",
                         "yes" if ok else "no",
                         str(c["nonlinear_iterations"]) if c else "-",
                         fmt(c["contact_force"], "%.6g") if ok else "-",
                         fmt(100 * rel(c["contact_force"], ref["contact_force"]), "%+.2f")
                         if ok and ref else "-",
                         fmt(c["contact_area"], "%.4g") if ok else "-",
                         fmt(c["extra"].get("max_penetration"), "%.2e") if ok else "-"])
    write_table("elasticity_theta_gamma",
                "3D model, θ × γ0 (Hertz block, Q1, 3318 DoFs; runs of "
                "tests/verification/elasticity_theta_gamma.py, test exit status %d)"
                % proc.returncode,
                ["θ", "γ0", "coercive", "conv.", "its", "force", "Δforce % (vs θ=1,γ0=100)",
                 "area", "max penetration"], rows,
                notes="Coercivity bound (theory 2.4, C_n = 2.21 for Q1 cubes): "
                      "γ0 > (1+θ)² C_n/4, i.e. θ = 1: γ0 > 2.2, θ = 0: γ0 > 0.55, "
                      "θ = −1: any γ0 > 0. Iteration limit 25.")


# --------------------------------------------------------------------------
# part c: fixed point vs Newton

def part_c(results):
    cases = []
    nk = (16,) if args.quick else (16, 32)
    if not args.quick:
        cases.append(("3D Q2, Nitsche θ=1 γ0=20", "8x8x1", "paper_3d.prm",
                      {"Geometry": {"Subdivisions": "8, 8, 1", "Number of cycles": 1}}))
    for n in nk:
        g = {"Geometry": {"Subdivisions": "%d, %d" % (n, n), "Number of cycles": 1}}
        cases.append(("Mindlin MITC4, Nitsche θ=1 γ0=200", "%d²" % n, "paper_mindlin.prm", g))
        cases.append(("Kirchhoff GSV θ=1 α·D=1e-4", "%d²" % n, "paper_kirchhoff.prm", g))
        cases.append(("Kirchhoff-Nitsche θ=1 γ0=200", "%d²" % n, "kirchhoff_nitsche.prm", g))
    for n in nk:
        g = {"Geometry": {"Subdivisions": "%d, %d" % (n, n), "Number of cycles": 1}}
        cases.append(("Mindlin MITC4, θ=0 γ0=2, friction F=0.2", "%d²" % n,
                      "paper_mindlin_friction.prm", g))
    rows = []
    for label, mesh, prm, over in cases:
        res = {}
        for scheme in ("newton", "fixed point"):
            o = dict(over)
            o["Nonlinear_solver"] = {"Scheme": scheme}
            name = "scheme_%s_%s_%s" % (prm[:-4], mesh.replace("²", ""), scheme.replace(" ", "_"))
            res[scheme] = run(name, paper_prm(prm, **o))
        cn, cf = (res[s]["cycles"][-1] if res[s]["cycles"] else None
                  for s in ("newton", "fixed point"))

        def conv_its(c, r):
            if converged(c):
                return str(c["nonlinear_iterations"])
            return "no (%s)" % (c["nonlinear_iterations"] if c else "-")
        dreact = (fmt(rel(cf["contact_force"], cn["contact_force"]), "%+.1e")
                  if converged(cn) and converged(cf) else "-")
        rows.append([label, mesh, str(cn["n_dofs"]) if cn else "-",
                     conv_its(cn, res["newton"]), conv_its(cf, res["fixed point"]),
                     fmt(cn["contact_force"], "%.6f") if converged(cn) else "-",
                     dreact, "%.1f" % res["newton"]["seconds"],
                     "%.1f" % res["fixed point"]["seconds"]])
    write_table("fixed_point_newton",
                "Fixed point vs Newton iterations on the paper's test (one cycle, cold start)",
                ["model", "mesh", "DoFs", "Newton its", "fixed-point its", "reaction (Newton)",
                 "Δreaction (fp)", "t Newton [s]", "t fp [s]"], rows,
                notes="'no (N)': stopped after N iterations without convergence (exit "
                      "status 2). Frictionless, the fixed point (contact status, slip "
                      "direction and friction threshold frozen at the previous iterate) "
                      "has the same linearisation as Newton, so the iterations coincide; "
                      "they differ only with friction.")


def main():
    global args
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("exe", help="the nitsche-contact executable")
    ap.add_argument("out", help="output directory for the tables")
    ap.add_argument("--parts", default="abcd", help="subset of abcd")
    ap.add_argument("--quick", action="store_true", help="small meshes, for testing the script")
    args = ap.parse_args()
    args.exe = os.path.abspath(args.exe)
    args.out = os.path.abspath(args.out)
    if not os.access(args.exe, os.X_OK):
        sys.exit("convergence_study: %s is not an executable" % args.exe)
    bad = set(args.parts) - set("abcd")
    if bad or not args.parts:
        sys.exit("convergence_study: --parts must be a non-empty subset of 'abcd', got '%s'"
                 % args.parts)
    os.makedirs(args.out, exist_ok=True)
    results = {}
    t0 = time.time()
    for p in "dabc":
        if p in args.parts:
            print("== part %s" % p, flush=True)
            globals()["part_" + p](results)
    with open(os.path.join(args.out, "tables.md"), "w") as f:
        f.write("Produced by `/usr/bin/python3 parameters/convergence_study.py %s` "
                "(%.0f s).\n\n" % (" ".join(sys.argv[1:]), time.time() - t0))
        f.write("\n".join(tables_md))
    print("tables written to %s (%.0f s)" % (args.out, time.time() - t0))


if __name__ == "__main__":
    main()
