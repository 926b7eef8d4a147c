"""'Output/Contact points': the per-point CSV (contact_points-NN.csv) of
every model against the program's other account of the same iterate, the
cycle records of summary.json (computed by each model's postprocessing and
by the driver's status counts), and the 3D file on 2 MPI ranks against 1.
Runs: the paper's test with each model on small meshes (3D 8 x 8 x 1 ->
16 x 16 x 1, Gauss-Lobatto contact points, gamma0 = 60; Mindlin with
friction F = 0.2, 8^2 -> 16^2, where the active points slip; Mindlin
MITC9, frictionless, 4^2 -> 8^2;
Kirchhoff GSV 16^2 -> 32^2).
Checks per cycle: one row per contact point (summary 'contact_points'),
the rows with status > 0 are the active points ('active_points', and
for Mindlin with friction 'stick_points' / 'slip_points' by status 1 / 2,
with slip rows present), sum of weight x pressure
is the contact force (relative 1e-9; 12 digits in the file), pressure >= 0 and positive only at
active points, s_n > 0 exactly at the inactive ones, the weights sum to
the plate area 100, and every point lies in its cell (within half the cell
size of the cell centre); the pressure column of profile-NN.csv is at
each point the mean of the rows of the cell (3D: bottom face) holding it.
3D: the files of 1 and 2 ranks hold the same
points (sorted by position and cell) with the same status and pressures
(within 1e-4 of the largest pressure: the Newton tolerance 1e-6 bounds
the energy norm of the error, measured pointwise differences 1.2e-5).
'Contact points per iteration' (Kirchhoff, and 3D on 2 ranks): per
cycle one file contact_points-NN-iKKK.csv per linear solve (KKK = 0 ...
nonlinear_iterations - 1), each against the iteration log of the driver:
its active rows are the 'contact A/B' of the line 'iteration KKK+1', and
the points whose status differs from file KKK-1 are that line's
'changed' count.
The 3D Nitsche parameter on cells taller and flatter than wide (an
unloaded block above a plane: s_n = r g at every point, r = gamma0 E / h_n
with h_n the cell height 2, 2/3 and 0.2, not its width 0.5 or its largest
side).
Finally parameters/plot_contact_points.py draws two of the files, and
with --against the status changes of two iterates."""
import csv, os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import (shipped_prm, parse_args, run, check, close, finish, read_vtu,
                    integrate_patch_field)

args = parse_args()
here = os.path.dirname(os.path.abspath(__file__))
parameters = os.path.join(here, "..", "..", "parameters")


def prm_from(name, replacements, per_iteration):
    return shipped_prm(name, replacements,
                       "\nsubsection Output\n  set Contact points = true\n"
                       "  set Contact points per iteration = %s\nend\n"
                       % ("true" if per_iteration else "false"))


def iteration_log(log):
    """{(cycle, k): (active, changed)} from the lines 'iteration k: ...'"""
    lines, cycle = {}, None
    for line in log.splitlines():
        m = re.match(r"Cycle (\d+):", line)
        if m:
            cycle = int(m.group(1))
        m = re.match(r"\s+iteration\s+(\d+): contact (\d+)/\d+.*changed (\d+)", line)
        if m:
            lines[(cycle, int(m.group(1)))] = (int(m.group(2)), int(m.group(3)))
    return lines


def check_iterates(name, summary, log):
    """The per-iteration files of run name against its iteration log."""
    lines = iteration_log(log)
    for record in summary["cycles"]:
        c, its = record["cycle"], record["nonlinear_iterations"]
        directory = os.path.join(args.workdir, name)
        present = sorted(f for f in os.listdir(directory)
                         if re.match(r"contact_points-%02d-i\d+\.csv$" % c, f))
        check(present == ["contact_points-%02d-i%03d.csv" % (c, k) for k in range(its)],
              "%s cycle %d: %d per-iteration files for %d iterations"
              % (name, c, len(present), its))
        previous = None
        agree = True
        for k in range(its):
            if k >= len(present) or (c, k + 1) not in lines:
                agree = False
                break
            with open(os.path.join(directory, present[k])) as f:
                status = [int(float(r["status"])) for r in csv.DictReader(f)]
            active, changed = lines[(c, k + 1)]
            agree = agree and sum(s > 0 for s in status) == active
            # (the driver counts stick <-> slip switches as changes too)
            if previous is not None:
                agree = agree and sum(a != b for a, b in zip(status, previous)) == changed
            previous = status
        check(agree, "%s cycle %d: active and changed points of the %d iterates as logged"
              % (name, c, its))


def read_points(name, cycle):
    path = os.path.join(args.workdir, name, "contact_points-%02d.csv" % cycle)
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


cases = [("elasticity", "paper_3d.prm",
          [("Number of cycles", "2"), ("Tolerance", "1e-6"),
           ("Refine through thickness", "false\n  set Contact quadrature rule = lobatto"),
           ("Nitsche gamma0", "60")], [1, 2]),
         ("mindlin", "paper_mindlin_friction.prm", [("Number of cycles", "2")], [1]),
         ("mindlin9", "paper_mindlin_mitc9.prm", [("Number of cycles", "2")], [1]),
         ("kirchhoff", "paper_kirchhoff.prm", [("Number of cycles", "2")], [1])]
per_iteration = {("elasticity", 2), ("kirchhoff", 1)}

files = {}
for tag, prm, changes, ranks in cases:
    for np in ranks:
        name = "%s_np%d" % (tag, np)
        summary, log = run(args, name,
                           prm_from(prm, changes, (tag, np) in per_iteration), np=np,
                           output_format="vtu")
        if (tag, np) in per_iteration:
            check_iterates(name, summary, log)
        for record in summary["cycles"]:
            c = record["cycle"]
            what = "%s cycle %d" % (name, c)
            pts = read_points(name, c)
            files[(tag, np, c)] = pts
            check(len(pts) == record["contact_points"],
                  "%s: %d rows, %d contact points" % (what, len(pts), record["contact_points"]))
            by_status = [sum(1 for p in pts if p["status"] == s) for s in (1, 2)]
            check(by_status[0] + by_status[1] == record["active_points"],
                  "%s: %d rows with status > 0, %d active points"
                  % (what, by_status[0] + by_status[1], record["active_points"]))
            if tag == "mindlin":
                check(by_status == [record["stick_points"], record["slip_points"]]
                      and by_status[1] > 0,
                      "%s: stick / slip rows %s, summary %d / %d"
                      % (what, by_status, record["stick_points"], record["slip_points"]))
            close(sum(p["weight"] * p["pressure"] for p in pts), record["contact_force"],
                  1e-9, what + ": sum of weight x pressure = contact force")
            close(sum(p["weight"] for p in pts), 100., 1e-9, what + ": sum of the weights")
            check(all(p["pressure"] >= 0. and (p["pressure"] == 0. or p["status"] > 0)
                      for p in pts), what + ": pressure >= 0, positive only at active points")
            check(all((p["s_n"] > 0.) == (p["status"] == 0) for p in pts),
                  what + ": s_n > 0 exactly at the inactive points")
            # The VTU's cell fields against the same points: contact_pressure
            # (the cell's or bottom face's mean of the points' pressures) and
            # contact_fraction (the share of the weights in contact)
            # integrate to the contact force and the contact area (float32
            # output: 1e-5); a pressure evaluated at the output points, between
            # the contact points, could exceed the largest point pressure
            # 1e4-fold.
            directory = os.path.join(args.workdir, name)
            pieces = sorted(f for f in os.listdir(directory)
                            if re.match(r"(contact-|solution_|kirchhoff_)%02d\.\d+\.vtu$"
                                        % c, f) and not (tag == "elasticity" and
                                                         f.startswith("solution_")))
            pieces = [read_vtu(os.path.join(directory, f)) for f in pieces]
            check(len(pieces) == np, "%s: %d VTU pieces for %d ranks" % (what, len(pieces), np))
            force = sum(integrate_patch_field(a, "contact_pressure")[0] for a in pieces)
            area = sum(integrate_patch_field(a, "contact_fraction")[0] for a in pieces)
            plate = sum(integrate_patch_field(a, "contact_pressure")[1] for a in pieces)
            close(force, record["contact_force"], 1e-5,
                  what + ": VTU contact_pressure integrates to the contact force")
            close(area, record["contact_area"], 1e-5,
                  what + ": VTU contact_fraction integrates to the contact area")
            close(plate, 100., 1e-6, what + ": the VTU covers the plate once")
            pmax = max(p["pressure"] for p in pts)
            check(max(max(a["contact_pressure"][0]) for a in pieces) <= pmax * (1 + 1e-6),
                  what + ": VTU contact_pressure at most the largest point pressure %g" % pmax)
            half = 0.5 * record["h"] * (1 + 1e-9)
            check(all(abs(p["x"] - p["cell_x"]) <= half and abs(p["y"] - p["cell_y"]) <= half
                      for p in pts), what + ": every point within its cell (h = %g)" % record["h"])
            # profile.csv's pressure column: at each point of the profile
            # line the mean pressure of the cell (3D: bottom face) that holds
            # it, the same as the weighted mean of that cell's rows here (a
            # point on a cell edge may take either cell's mean, or their mean)
            cells = {}
            for p in pts:
                sums = cells.setdefault((p["cell_x"], p["cell_y"]), [0., 0.])
                sums[0] += p["weight"] * p["pressure"]
                sums[1] += p["weight"]
            xs = sorted({k[0] for k in cells})
            half = 0.5 * min(b - a for a, b in zip(xs, xs[1:])) * (1 + 1e-9)
            with open(os.path.join(directory, "profile-%02d.csv" % c)) as f:
                profile = list(csv.DictReader(f))
            worst = 0.
            for row in profile:
                x, y, value = float(row["x"]), float(row["y"]), float(row["pressure"])
                means = [a / b for (cx, cy), (a, b) in cells.items()
                         if abs(x - cx) <= half and abs(y - cy) <= half]
                worst = max(worst, max(0., min(means) - value, value - max(means)))
            check(len(profile) > 100 and worst <= 1e-8 * max(pmax, 1e-300),
                  "%s: profile.csv pressure = its cell's mean pressure of the rows "
                  "(%d points, largest deviation %.1e)" % (what, len(profile), worst))

for c in (0, 1):
    key = lambda p: (round(p["x"], 9), round(p["y"], 9), round(p["cell_x"], 9),
                     round(p["cell_y"], 9))
    a = sorted(files[("elasticity", 1, c)], key=key)
    b = sorted(files[("elasticity", 2, c)], key=key)
    pmax = max(p["pressure"] for p in a)
    same = len(a) == len(b) and all(
        key(p) == key(q) and p["status"] == q["status"]
        and abs(p["pressure"] - q["pressure"]) <= 1e-4 * pmax for p, q in zip(a, b))
    check(same, "elasticity cycle %d: the same points, statuses and pressures on 1 and 2 ranks" % c)

# The 3D Nitsche parameter r = gamma0 E / h_n with h_n the height of the
# cell normal to the contact face (|K| / |F|), on cells taller and flatter
# than wide: an unloaded clamped block 1 x 1 x T held 0.1 above a plane
# stays at u = 0, so every contact point is inactive with s_n = sigma_n -
# r (u_n - g) = r g exactly; with 2 x 2 x L cells (0.5 wide, T / L high)
# r must be gamma0 E L / T, not built on the width (0.5), the largest side
# or the diameter.
TALL = """
set Model = elasticity
subsection Geometry
  set Length x = 1
  set Length y = 1
  set Thickness = %r
  set Boundary conditions = all: clamped
  set Subdivisions = 2, 2, %d
end
subsection Material
  set Young's modulus = 100
end
subsection Load
  set Transverse load = 0
end
subsection Obstacle
  set Level = %r
end
subsection Contact
  set Nitsche gamma0 = 20
end
subsection Elasticity
  set Polynomial degree = %d
end
subsection Output
  set Contact points = true
end
"""
for thickness, layers, degree in ((2.0, 1, 2), (2.0, 3, 1), (0.2, 1, 2)):
    name = "cell_height_%g_%d_Q%d" % (thickness, layers, degree)
    run(args, name, TALL % (thickness, layers, -thickness / 2 - 0.1, degree))
    with open(os.path.join(args.workdir, name, "contact_points-00.csv")) as f:
        pts = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    r = 20 * 100 / (thickness / layers)
    check(len(pts) > 0 and all(p["status"] == 0 and abs(p["gap"] - 0.1) <= 1e-12 and
                               abs(p["s_n"] - r * 0.1) <= 1e-9 * r for p in pts),
          "3D cells 0.5 x 0.5 x %.4g, Q%d: s_n = r g at all %d points with r = gamma0 E / h_n "
          "= %g (h_n = the cell height)" % (thickness / layers, degree, len(pts), r))

# The plotting tool of the parameters/ directory draws these files.
import subprocess
python = sys.executable
if subprocess.run([python, "-c", "import matplotlib"], capture_output=True).returncode != 0:
    python = "/usr/bin/python3"  # Debian's, with python3-matplotlib
png = os.path.join(args.workdir, "contact_points.png")
proc = subprocess.run([python, os.path.join(parameters, "plot_contact_points.py"),
                       os.path.join(args.workdir, "elasticity_np2", "contact_points-01.csv") + ":3D",
                       os.path.join(args.workdir, "mindlin_np1", "contact_points-01.csv"),
                       "--window", "0", "5", "0", "5", "-o", png],
                      capture_output=True, text=True)
check(proc.returncode == 0 and os.path.getsize(png) > 10000,
      "plot_contact_points.py draws two panels (%s)" % (proc.stdout.strip() or proc.stderr.strip()))
k_dir = os.path.join(args.workdir, "kirchhoff_np1")
png = os.path.join(args.workdir, "contact_points_against.png")
proc = subprocess.run([python, os.path.join(parameters, "plot_contact_points.py"),
                       os.path.join(k_dir, "contact_points-01-i000.csv") + ":start",
                       os.path.join(k_dir, "contact_points-01-i001.csv"),
                       "--against", os.path.join(k_dir, "contact_points-01.csv"), "-o", png],
                      capture_output=True, text=True)
check(proc.returncode == 0 and os.path.getsize(png) > 10000,
      "plot_contact_points.py --against draws the status changes (%s)"
      % (proc.stdout.strip() or proc.stderr.strip()))
proc = subprocess.run([python, os.path.join(parameters, "plot_contact_points.py"),
                       os.path.join(k_dir, "contact_points-01-i000.csv"),
                       "--against", os.path.join(k_dir, "contact_points-00.csv"), "-o", png],
                      capture_output=True, text=True)
check(proc.returncode != 0 and "same points" in proc.stderr,
      "plot_contact_points.py --against refuses files of different meshes")
finish()
