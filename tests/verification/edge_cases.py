"""Legal but unusual input, each
checked against an independent source:

1. A free plate lifted by a flat obstacle above it (Level 0.5) rests on it:
   its solution is a rigid translation up to the load's compression, which
   the energy seminorm of the stopping test cannot measure. Closed form:
   the plate's lower face lies on the obstacle, so the centre deflection is
   0.5 + t/2 (plates: bottom-face convention; 3D: the mid-plane's u3 within
   the compression t q / E), and the reaction equals the total load q a^2
   (equilibrium). All three models, each must converge (exit 0), also with
   Coulomb friction (F = 0.2) for the 3D and Mindlin models.
2. The 3D model on more MPI ranks than cells (1 cell, 2 ranks) with VTU
   output: one rank has no cells; the run must exit 0, write every piece
   of the contact output, and give the 1-rank summary (second method).
3. The file printed by --print-parameters, with only the output directory
   changed, must run (exit 0, converged) and satisfy equilibrium bounds
   (0 < reaction < total load q a^2, the plate clamped at its edges).
4. A cycle that does not converge (iteration limit 2) exits 2 and leaves
   summary.json with that cycle marked converged = false and no results
   (null, not zeros).
5. 'Nitsche theta = -1.0' is the run of '-1' (the same program).
6. Kirchhoff min/max deflection on a single simply supported cell: the
   vertices are held at 0, the interior is not; min_deflection must equal
   the minimum of the field sampled on a 101 x 101 grid (field.csv, a
   second evaluation of the same field at other points) to 1e-3.
7. A sphere smaller than the plate: where it does not
   reach, the VTU gap fields must be NaN (README), not the internal
   sentinel 1e30: the 3D contact file's initial_gap and penetration at the
   output points, the Kirchhoff cell field gap (a cell mean, NaN only where
   no point of the cell has the sphere below). Independent check: the
   points with NaN are exactly those outside the sphere's disc, and the
   finite values are bounded by the geometry (gap <= R + |z_c| + t).
8. 'Nonlinear solver/Damping after': on the Mindlin paper test with theta = 0 (no energy, so
   the damped steps are Armijo backtracking on |R|), 'Damping after = 3'
   must say "no convergence after 3 full steps: switching to damped steps"
   and '= 0' damp from the first step (whose full step this test's run
   does not accept: the first log line shows a step < 1); both must reach
   the solution of the
   default run (the same discrete problem: probes and reaction to 1e-6).
9. A free Mindlin plate lifted far (Level 1e7): |U| is the rigid lift, so
   the stopping test relative to |U| passes with the deformation still
   wrong (reaction 98 times the load). The
   equilibrium check of the accepted iterate must stop it with exit
   status 2 and its message; the same plate lifted by 0.5 (item 1) passes
   the check (relative_residual <= 1e-4 in summary.json). A clamped plate
   with t = 0.001 and the paper's load scaled by t^3 (a right solution
   whose residual sits at the round-off of the contact terms r (u_n - g),
   about 2e-3 of the load) must pass with a
   warning, and its reaction per load must be the t = 0.01 plate's within
   1 % (the Kirchhoff limit is the same plate; the gap differs by
   (0.01 - 0.001)/2 against 0.995).
"""
import csv
import json
import os
import shutil
import subprocess
from common import parse_args, run, check, close, finish, read_vtu

args = parse_args()
q, a, t = 0.02, 10.0, 0.01
total = q * a * a

# 1. free plates lifted by the obstacle
LIFT = """
set Model = %s
subsection Geometry
  set Subdivisions = %s
  set Boundary conditions = all: free
  set Number of cycles = 1
end
subsection Obstacle
  set Level = 0.5
end
subsection Nonlinear solver
  set Maximum iterations = 100
end
"""
FRICTION = "subsection Contact\n  set Friction coefficient = 0.2\nend\n"
for model, sub, extra in [("kirchhoff", "8, 8", ""), ("mindlin", "8, 8", ""),
                          ("elasticity", "4, 4, 1", ""), ("mindlin", "8, 8", FRICTION),
                          ("elasticity", "4, 4, 1", FRICTION)]:
    name = model + (" with friction" if extra else "")
    s, log = run(args, "lift_" + model + ("_friction" if extra else ""),
                 LIFT % (model, sub) + extra)
    c = s["cycles"][-1] if s else None
    check(c is not None and c["converged"], name + ": lifted free plate converged")
    if not c:
        continue
    # the 3D pressure r (u_n - g) cancels r g ~ 2e8 to give q: round-off
    # of about 1e-6 relative
    close(c["contact_force"], total, 1e-5 if model == "elasticity" else 1e-6,
          name + ": reaction = total load q a^2")
    # the lower face moves from -t/2 to 0.5; the 3D mid-plane displacement
    # differs by the compression of half the plate, below t q / E = 1e-9
    close(c["probes"][0], 0.5 + t / 2, 1e-6 if model == "elasticity" else 1e-9,
          name + ": deflection at the centre = 0.5 + t/2")

# 2. more ranks than cells, VTU output
ONE_CELL = """
set Model = elasticity
subsection Geometry
  set Subdivisions = 1, 1, 1
  set Number of cycles = 1
end
"""
one, _ = run(args, "one_cell_np1", ONE_CELL, pinned=False)  # as the run on 2 ranks below
outdir = os.path.join(args.workdir, "one_cell_np2_vtu")
shutil.rmtree(outdir, ignore_errors=True)
prm = os.path.join(args.workdir, "one_cell_np2_vtu.prm")
with open(prm, "w") as f:
    f.write(ONE_CELL + "subsection Output\n  set Directory = %s\n  set Format = vtu\nend\n" % outdir)
proc = subprocess.run([args.mpiexec or "mpiexec", "-np", "2", args.exe, prm],
                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                      cwd=args.workdir)
check(proc.returncode == 0, "1 cell on 2 ranks with VTU output: exit 0 (got %d)" % proc.returncode)
if proc.returncode != 0:
    print(proc.stdout[-2000:])
for piece in ["contact-00.pvtu", "contact-00.0000.vtu", "contact-00.0001.vtu",
              "solution_00.pvtu", "summary.json"]:
    check(os.path.exists(os.path.join(outdir, piece)), "1 cell on 2 ranks: %s written" % piece)
if os.path.exists(os.path.join(outdir, "summary.json")) and one:
    two = json.load(open(os.path.join(outdir, "summary.json")))
    a1, a2 = one["cycles"][0], two["cycles"][0]
    check(a2["converged"], "1 cell on 2 ranks: converged")
    close(a2["probes"][0], a1["probes"][0], 1e-8, "1 cell: centre deflection, 2 vs 1 ranks")

# 3. the all-defaults parameter file
defaults = subprocess.run([args.exe, "--print-parameters"], stdout=subprocess.PIPE,
                          text=True, check=True).stdout
s, _ = run(args, "defaults", defaults)
c = s["cycles"][-1] if s else None
check(c is not None and c["converged"], "--print-parameters file: converged")
if c:
    check(0. < c["contact_force"] < total,
          "--print-parameters file: 0 < reaction %.6g < q a^2 = %g" % (c["contact_force"], total))

# 4. a cycle that does not converge
FAIL = """
set Model = kirchhoff
subsection Geometry
  set Subdivisions = 16, 16
  set Number of cycles = 1
end
subsection Nonlinear solver
  set Maximum iterations = 2
end
"""
s, _ = run(args, "not_converged", FAIL, expect_status=2)
c = s["cycles"][-1] if s else None
check(c is not None and not c["converged"], "iteration limit 2: cycle marked converged = false")
if c:
    for key in ["contact_area", "contact_force", "min_deflection", "max_deflection", "probes"]:
        check(c[key] is None, "iteration limit 2: %s is null (%r)" % (key, c[key]))

# 5. 'Nitsche theta' accepts any spelling of the
# numbers 1, 0, -1: "-1.0" must give the run of "-1" (the same program).
THETA = FAIL.replace("set Maximum iterations = 2", "set Maximum iterations = 100") + \
    "subsection Contact\n  set Nitsche theta = %s\nend\n"
s1, _ = run(args, "theta_m1", THETA % "-1")
s2, _ = run(args, "theta_m1_0", THETA % "-1.0")
if s1 and s2:
    check(s1["cycles"][0]["contact_force"] == s2["cycles"][0]["contact_force"],
          "theta = -1.0 gives the run of theta = -1")
else:
    check(False, "theta = -1 and -1.0 both ran")

# 6. Kirchhoff extremes on one simply supported cell, obstacle far below
SS = """
set Model = kirchhoff
subsection Geometry
  set Subdivisions = 1, 1
  set Boundary conditions = all: simply supported
  set Number of cycles = 1
end
subsection Obstacle
  set Level = -100
end
subsection Output
  set Field grid points = 101
end
"""
s, _ = run(args, "ss_one_cell", SS)
c = s["cycles"][-1] if s else None
field = os.path.join(args.workdir, "ss_one_cell", "field.csv")
if c and os.path.exists(field):
    with open(field) as f:
        next(f)
        dense = min(float(line.split(",")[2]) for line in f)
    check(dense < 0., "one SS cell: the field dips to %.6g < 0 inside the cell" % dense)
    close(c["min_deflection"], dense, 1e-3, "one SS cell: min_deflection vs 101x101 field grid")
else:
    check(False, "one SS cell: summary and field.csv written")

# 7. no obstacle below part of the plate: NaN in the VTU gap fields
centre, radius = (5., 5., -2.), 2.
SPHERE = """
set Model = %s
subsection Geometry
  set Subdivisions = %s
  set Number of cycles = 1
end
subsection Load
  set Transverse load = 0
end
subsection Obstacle
  set Type = sphere
  set Sphere center = %s
  set Sphere radius = 2
end
subsection Output
  set Contact points = true
end
"""
for model, sub, piece, fields in [("elasticity", "8, 8, 1", "contact-00.0000.vtu",
                                   ["initial_gap", "penetration"]),
                                  ("kirchhoff", "8, 8", "kirchhoff_00.0.vtu", ["gap"])]:
    s, _ = run(args, "sphere_" + model, SPHERE % (model, sub, "5, 5, -2"),
               output_format="vtu")
    path = os.path.join(args.workdir, "sphere_" + model, piece)
    check(s is not None and os.path.exists(path), model + ", small sphere: VTU written")
    if not os.path.exists(path):
        continue
    vtu = read_vtu(path)
    points, dim = vtu["Points"]
    bound = radius + abs(centre[2]) + t
    for name in fields:
        values = vtu[name][0]
        finite = [v for v in values if v == v]
        check(len(finite) < len(values) and all(abs(v) <= bound for v in finite),
              "%s, small sphere: %s NaN at %d of %d points, finite values within %g "
              "(largest %.3g)" % (model, name, len(values) - len(finite), len(values),
                                  bound, max(abs(v) for v in finite) if finite else 0.))
    if model == "elasticity":
        # the output point lies outside the disc exactly where there is NaN
        outside = [(points[dim * i] - centre[0]) ** 2 + (points[dim * i + 1] - centre[1]) ** 2
                   >= radius ** 2 for i in range(len(vtu["initial_gap"][0]))]
        nan = [v != v for v in vtu["initial_gap"][0]]
        check(outside == nan, "3D, small sphere: initial_gap NaN exactly outside the disc")
    # the contact-point file: gap and s_n nan exactly outside the disc (the
    # internal sentinel 1e30 must not show)
    with open(os.path.join(args.workdir, "sphere_" + model, "contact_points-00.csv")) as f:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    outside = [(p["x"] - centre[0]) ** 2 + (p["y"] - centre[1]) ** 2 >= radius ** 2
               for p in rows]
    for name in ("gap", "s_n"):
        check([p[name] != p[name] for p in rows] == outside and any(outside),
              "%s, small sphere: contact points' %s nan exactly outside the disc" % (model, name))
    check(all(abs(p["gap"]) <= bound for p, o in zip(rows, outside) if not o),
          "%s, small sphere: finite gaps within %g" % (model, bound))
    # no obstacle below any point: max_penetration is null, not -1e30
    far, _ = run(args, "far_sphere_" + model, SPHERE % (model, sub, "500, 500, -2"))
    check(far["cycles"][-1]["extra"]["max_penetration"] is None,
          "%s, sphere beside the plate: max_penetration null (%s)"
          % (model, far["cycles"][-1]["extra"]["max_penetration"]))

# 8. 'Damping after'
DAMP = """
set Model = mindlin
subsection Geometry
  set Length x = 10
  set Length y = 10
  set Thickness = 0.01
  set Subdivisions = 8, 8
end
subsection Load
  set Transverse load = -0.02
end
subsection Obstacle
  set Level = -1
end
subsection Contact
  set Nitsche theta = 0
end
subsection Nonlinear solver
  set Tolerance = 1e-8
  set Maximum iterations = 200
  set Damping after = %s
end
subsection Output
  set Probe points = 5, 5; 2.5, 5; 1, 5
end
"""
ref, _ = run(args, "damping_default", DAMP % "100000")
for after in ("3", "0"):
    s, log = run(args, "damping_after_" + after, DAMP % after)
    if after == "3":
        check("no convergence after 3 full steps: switching to damped steps" in log,
              "Damping after = 3: the log says so")
    else:
        # damped from the start: the first step already backtracks, and no
        # rule has to switch later
        first = next((l for l in log.splitlines() if "iteration   1:" in l), "")
        check(" step 0." in first and "switching to damped steps" not in log,
              "Damping after = 0: damped from the first step (%s)" % first.strip())
    a, b = ref["cycles"][-1], s["cycles"][-1]
    check(b["converged"], "Damping after = %s: converged (%d iterations, default %d)"
          % (after, b["nonlinear_iterations"], a["nonlinear_iterations"]))
    for k in range(3):
        close(b["probes"][k], a["probes"][k], 1e-6,
              "Damping after = %s: probe %d as in the default run" % (after, k))
    close(b["contact_force"], a["contact_force"], 1e-6,
          "Damping after = %s: reaction as in the default run" % after)
# 9. the equilibrium check of the Mindlin model
FAR = """set Model = mindlin
subsection Geometry
  set Subdivisions = 2, 2
  set Boundary conditions = all: free
end
subsection Obstacle
  set Level = %s
end
"""
# A free plate lifted far: the round-off of the gap swamps the
# deformation, and the Newton path that round-off steers ends in one of the
# program's non-convergence reports (exit status 2), most often the
# equilibrium check after a stopping test passed on the rigid motion.
REPORTS = ("the accepted iterate is not an equilibrium", "stagnated", "did not converge",
           "singular or too ill-conditioned")
equilibrium_check = 0
for level in ("1e11", "1e12", "1e13"):
    _, log = run(args, "mindlin_lifted_" + level, FAR % level, expect_status=2)
    check(any(r in log for r in REPORTS),
          "Mindlin plate lifted by %s: exit status 2 with a non-convergence report" % level)
    equilibrium_check += REPORTS[0] in log
check(equilibrium_check > 0, "Mindlin plate lifted far: the equilibrium check stops %d of "
      "the 3 runs" % equilibrium_check)
s, _ = run(args, "mindlin_lifted_near", FAR % "0.5")
check(s["cycles"][-1]["extra"]["relative_residual"] <= 1e-4,
      "Mindlin plate lifted by 0.5: |R|/|AU| = %.3g <= 1e-4"
      % s["cycles"][-1]["extra"]["relative_residual"])
close(s["cycles"][-1]["contact_force"], 2.0, 1e-6,
      "Mindlin plate lifted by 0.5: the obstacle carries the load 0.02 x 100")
paper_mindlin = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                  "parameters", "paper_mindlin.prm")).read()
reactions = {}
for t_plate in (0.01, 0.001):
    text = paper_mindlin + ("\nsubsection Geometry\n  set Thickness = %r\n"
                            "  set Number of cycles = 2\nend\n"
                            "subsection Load\n  set Transverse load = %r\nend\n"
                            % (t_plate, -0.02 * (t_plate / 0.01) ** 3))
    s, log = run(args, "mindlin_thin_%g" % t_plate, text)
    c = s["cycles"][-1]
    rr = c["extra"]["relative_residual"]
    if t_plate < 0.01:
        check(1e-4 < rr <= 1e-2 and "warning: the residual of the accepted iterate is" in log,
              "Mindlin t = 0.001: converged (exit 0) with the round-off warning, "
              "|R|/max(|AU|,|F|) = %.3g" % rr)
    reactions[t_plate] = c["contact_force"] / (0.02 * (t_plate / 0.01) ** 3 * 100)
close(reactions[0.001], reactions[0.01], 1e-2,
      "Mindlin t = 0.001 against t = 0.01: reaction per total load")
finish()
