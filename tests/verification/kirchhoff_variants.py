"""The clamped unit square (D = 1, q = 1 downwards) on the flat obstacle
psi = -5e-4 (the free plate would reach -1.265e-3, so a genuinely 2D
contact zone forms and the D Delta^2 v terms of GSV are exercised):
 - theta = 1, 0, -1 agree to discretisation accuracy: their differences in
   contact force and deflection are below the change of the theta = 1
   result between the 16x16 and 32x32 meshes;
 - pure penalty (alpha = 0) with compliance kappa -> 0 approaches the
   rigid-obstacle (kappa = 0) GSV solution, the difference shrinking
   roughly like kappa;
 - the fixed-point and Newton schemes give the same solution;
 - the 'Kirchhoff with Nitsche' formulation gives a solution close to GSV
   (it differs by the O(t^2 |curvature|) shift of doc/theory.md 4.7)."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, close, check, finish
from kirchhoff_lib.plate import plate_prm, E_UNIT_D

args = parse_args()
probes = "0.5, 0.5; 0.2, 0.5; 0.1, 0.1"
base = dict(sub=(16, 16), cycles=2, load=-1, level=-5e-4, probes=probes)
res = {}
for theta in (1, 0, -1):
    s, _ = run(args, "theta%d" % theta, plate_prm(theta=theta, **base))
    check(all(c["converged"] for c in s["cycles"]), "theta=%d converged" % theta)
    res[theta] = s["cycles"]
f1 = [c["contact_force"] for c in res[1]]
w1 = [c["probes"][1] for c in res[1]]
disc_f, disc_w = abs(f1[1] - f1[0]), abs(w1[1] - w1[0])
check(res[1][-1]["active_points"] > 0 and f1[-1] > 0.1,
      "contact zone present: force %.5f, %d active points" % (f1[-1], res[1][-1]["active_points"]))
for theta in (0, -1):
    df = abs(res[theta][-1]["contact_force"] - f1[1])
    dw = abs(res[theta][-1]["probes"][1] - w1[1])
    check(df < disc_f, "theta=%d vs 1: force difference %.2e < discretisation change %.2e"
          % (theta, df, disc_f))
    check(dw < disc_w, "theta=%d vs 1: w(0.2,0.5) difference %.2e < discretisation change %.2e"
          % (theta, dw, disc_w))

# pure penalty with decreasing compliance: deflections approach the rigid
# (kappa = 0) GSV solution
ref_f = f1[1]
ref_w = res[1][-1]["probes"]
diffs = []
for kappa in (1e-5, 1e-6, 1e-7):
    s, _ = run(args, "penalty%g" % kappa, plate_prm(alpha=0, kappa=kappa, **base))
    check(all(c["converged"] for c in s["cycles"]), "penalty kappa=%g converged" % kappa)
    w = s["cycles"][-1]["probes"]
    diffs.append(max(abs(w[0] - ref_w[0]), abs(w[1] - ref_w[1])))
    print("      penalty kappa=%g: force %.8f, max deflection difference to kappa=0 GSV %.3e"
          % (kappa, s["cycles"][-1]["contact_force"], diffs[-1]))
check(diffs[0] > 5 * diffs[1] and diffs[1] > 3 * diffs[2],
      "penalty -> GSV as kappa -> 0 (about linearly): %s" % diffs)
check(diffs[2] < 1e-3 * 5e-4, "penalty kappa=1e-7 within 1e-3 g0 of the rigid solution")
close(s["cycles"][-1]["contact_force"], ref_f, 1e-3, "penalty kappa=1e-7 vs rigid GSV force")

# compliant obstacle, GSV with kappa > 0 vs pure penalty with the same kappa
s, _ = run(args, "gsv_kappa", plate_prm(kappa=1e-5, **base))
sp, _ = run(args, "penalty_kappa", plate_prm(alpha=0, kappa=1e-5, **base))
close(s["cycles"][-1]["contact_force"], sp["cycles"][-1]["contact_force"], 5e-3,
      "compliant obstacle kappa=1e-5: GSV(alpha*D=1e-4) vs pure penalty force")

# fixed point vs Newton (identical for frictionless contact)
s, _ = run(args, "fixed_point", plate_prm(scheme="fixed point", **base))
for a, b in zip(s["cycles"], res[1]):
    check(a["nonlinear_iterations"] == b["nonlinear_iterations"],
          "cycle %d: fixed point and Newton iterations %d == %d"
          % (a["cycle"], a["nonlinear_iterations"], b["nonlinear_iterations"]))
    close(a["contact_force"], b["contact_force"], 1e-10, "cycle %d: fixed point vs Newton force" % a["cycle"])
    close(a["probes"][1], b["probes"][1], 1e-10, "cycle %d: fixed point vs Newton w(0.2,0.5)" % a["cycle"])

# Kirchhoff with Nitsche (3D Nitsche term with Kirchhoff kinematics). Its
# theta-term -(theta/r) lambda^2 (t/2)^2 (Delta w, Delta v) acts on the whole
# plate and changes the bending stiffness by a relative O(theta/gamma0)
# (about 0.9 theta/gamma0 for nu = 0.3): theta = 0 must agree with GSV,
# theta = +-1 must approach it like 1/gamma0.
for theta in (0, 1, -1):
    dev = []
    for g in (20, 200):
        extra = "subsection Contact\n  set Nitsche gamma0 = %g\nend\n" % g
        s, _ = run(args, "kn%d_%d" % (theta, g),
                   plate_prm(formulation="nitsche", theta=theta, extra=extra, **base))
        check(all(c["converged"] for c in s["cycles"]),
              "Kirchhoff-Nitsche theta=%d gamma0=%g converged" % (theta, g))
        dev.append(abs(s["cycles"][-1]["contact_force"] - ref_f) / ref_f)
        print("      Kirchhoff-Nitsche theta=%d gamma0=%g: force %.8f, rel. deviation from GSV %.3e"
              % (theta, g, s["cycles"][-1]["contact_force"], dev[-1]))
    if theta == 0:
        check(max(dev) < 1e-4, "Kirchhoff-Nitsche theta=0 agrees with GSV (force within 1e-4)")
    else:
        check(dev[0] < 0.1 and 5 < dev[0] / dev[1] < 20,
              "Kirchhoff-Nitsche theta=%d: deviation ~ 1/gamma0 (ratio %.2f for gamma0 x10)"
              % (theta, dev[0] / dev[1]))

# The same theta-term exactly, away from contact: a hard simply supported
# square (D = 1) whose obstacle is far below. Every point is inactive and
# the Kirchhoff-Nitsche form is a(w,v) - (theta/r) int sigma_n(w) sigma_n(v)
# with sigma_n = lambda (t/2) Delta w (3D Hooke law with Kirchhoff
# kinematics on the lower face, doc/theory.md 4.7) and r = gamma0 E / t. On
# a simply supported rectangle int D2w:D2v = int Dw Dv for w, v vanishing
# on the edges, so the form is (D - theta c) int Dw Dv with c = lambda^2
# (t/2)^2 / r: the discrete solutions of theta = 1, -1 are that of theta = 0
# scaled by D / (D - theta c), exactly (same space, same quadrature).
lam = E_UNIT_D * 0.3 / (1.3 * 0.4)
c_theta = lam ** 2 * 0.005 ** 2 / (20 * E_UNIT_D / 0.01)
ss = dict(sub=(8, 8), edges="all: simply supported", formulation="nitsche",
          extra="subsection Contact\n  set Nitsche gamma0 = 20\nend\n")
w_ss = {}
for theta in (0, 1, -1):
    s, _ = run(args, "kn_far%d" % theta, plate_prm(theta=theta, **ss))
    check(s["cycles"][-1]["converged"] and s["cycles"][-1]["active_points"] == 0,
          "Kirchhoff-Nitsche far obstacle theta=%d: converged, no contact" % theta)
    w_ss[theta] = s["cycles"][-1]["probes"][0]
close(w_ss[0], 0.0040623527, 1e-3, "Kirchhoff-Nitsche far obstacle theta=0: w(centre) = "
      "0.0040623527 q a^4/D (hard simply supported)")
for theta in (1, -1):
    close(w_ss[theta] / w_ss[0], 1 / (1 - theta * c_theta), 1e-8,
          "Kirchhoff-Nitsche far obstacle theta=%d: w / w(theta=0) = D/(D - theta c), "
          "c/D = %.5f" % (theta, c_theta))

# A plate resting on the obstacle from the start (paper's plate, obstacle at
# the bottom face, Level = -t/2): the solution is w = 0 and the obstacle
# carries the whole load, reaction q * area = 0.02 * 100 = 2 (equilibrium,
# independent of the method). |dU|_a/|U|_a has no scale at a zero solution;
# the residual test relative to the load vector must end the iteration.
here = os.path.dirname(os.path.abspath(__file__))
paper = open(os.path.join(here, "..", "..", "parameters", "paper_kirchhoff.prm")).read()
for theta in (1, -1):
    resting, _ = run(args, "resting%d" % theta, paper +
                     "\nsubsection Geometry\n  set Number of cycles = 2\nend\n"
                     "subsection Obstacle\n  set Level = -0.005\nend\n"
                     "subsection Contact\n  set Nitsche theta = %d\nend\n" % theta)
    for cyc in resting["cycles"]:
        c = "resting plate, theta = %d, cycle %d: " % (theta, cyc["cycle"])
        check(cyc["converged"] and cyc["nonlinear_iterations"] <= 5,
              c + "converged in %d iterations" % cyc["nonlinear_iterations"])
        close(cyc["contact_force"], 2.0, 1e-10, c + "reaction = q * area")
        close(cyc["contact_area"], 100.0, 1e-12, c + "contact area = plate area")
        check(max(abs(cyc["min_deflection"]), abs(cyc["max_deflection"])) < 1e-12,
              c + "w = 0 (|w| <= %.1e)" % max(abs(cyc["min_deflection"]), abs(cyc["max_deflection"])))
finish()
