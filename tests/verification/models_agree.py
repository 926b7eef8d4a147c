"""The paper's test (clamped [0,10]^2, t = 0.01, E = 2e5, nu = 0.3,
q = -0.02, rigid plane x3 = -1, frictionless) solved on coarse, matching
meshes by all three models agrees: the 3D model (Q2, 16x16x1 cells, the
parameters of parameters/paper_3d.prm), the Reissner-Mindlin plate (MITC4,
8^2 -> 32^2 nested, parameters/paper_mindlin.prm) and the Kirchhoff plate
(GSV, BFS, 16^2, parameters/paper_kirchhoff.prm); all three have nodes
0.3125 apart. The model error between 3D and plates is O((t/a)^2) = 1e-6,
so every difference is discretisation (or the theta-bias of Mindlin's
inserted Nitsche terms, 0.45 % for theta = 1, gamma0 = 200).

Plates (Mindlin 32^2 vs GSV 16^2). Measured: reaction -0.14 %,
w(2.5,5) -0.21 %, w(2.5,2.5) -0.19 %, w(1,5) -2.0 %. The EOC tables of
doc/convergence.md (parameters/convergence_study.py) give each run's own
error against a 256^2 reference of the same model: Mindlin 32^2 reaction
-0.28 %, w(2.5,5) -0.27 %, w(2.5,2.5) -0.36 %, w(1,5) -2.2 %; GSV 16^2
at most 0.11 %; and the two 256^2 references differ by the theta-bias,
+0.14 % (reaction), +0.01 %, +0.06 %, +0.13 %. The sums of these bounds
are 0.43 %, 0.32 %, 0.53 %, 2.4 %. Tolerances: 0.5 % (reaction, w(2.5,5)),
0.6 % (w(2.5,2.5)) and 3 % (w(1,5), where the curvature is largest).
The same Mindlin run with 'Contact formulation = gsv' (gamma0 = auto) has
no bias; its errors against the 256^2 plates (Kirchhoff GSV; MITC9 gsv
agrees with it to 7e-5, doc/mindlin.md) are -0.29 %, -0.27 %, -0.36 %,
-2.23 %, so with GSV 16^2's 0.11 % the sums are 0.40 %, 0.38 %, 0.47 %,
2.34 %: tolerances 0.45 %, 0.45 %, 0.55 % and 2.5 % (measured: -0.29 %,
-0.23 %, -0.25 %, -2.2 %; the paper's form is closer on this mesh only
because its bias offsets part of MITC4's discretisation error).

3D (16x16x1 Q2) vs GSV 16^2. The 3D mesh is much coarser relative to
what it must resolve (one Q2 element spans 62 thicknesses; it is stiffer
than the plate): measured reaction -2.78 %, |w| at (2.5,5) -0.91 %, at
(2.5,2.5) -2.30 %, at (1,5) -7.9 %; with 8x8x1 cells the same numbers
are -12.9 %, -1.3 %, -6.8 %, -31 %, so the difference is discretisation
(it shrinks by 4-5x per refinement; a 32x32x1 run, 9.7 min, too long for
this test, gives -0.72 %, -0.24 %, -0.48 %, -2.5 %; doc/results.md:
16x16x2 gives the same as 16x16x1, so in-plane resolution is what
matters). Because the 3D
difference is a few percent, the test brackets it from both sides with
independent values instead of a symmetric tolerance:
 - a linear run (obstacle removed) of the same 3D mesh against the
   published centre deflection of the clamped square plate,
   0.00126532 q a^4/D (Timoshenko & Woinowsky-Krieger's 0.00126, to 6
   digits as in doc/theory.md 6.1 and kirchhoff_linear.py): measured -2.12 %, i.e. the mesh is 2.2 % too stiff (checked:
   stiffer, by less than 3 %);
 - upper bound: a Kirchhoff GSV plate (32^2) made stiffer by exactly this
   measured factor (E * w_exact/|w_3D|) carries reaction 0.7460 (-0.72 %)
   and deflects |w| -0.01 % / -0.18 % / -0.64 % less at the probes; the 3D
   run must carry no more than this plate (reaction, |w| at the three
   probes), because the 3D discretisation error is not a uniform
   stiffening but concentrated where the curvature is large (near the
   clamped edges and the free boundary of the contact zone), which moves
   still more load from the obstacle to the edges;
 - lower bound: at most 4 % (reaction), 2 % (w(2.5,5)), 4 % (w(2.5,2.5)),
   11 % (w(1,5)) below GSV 16^2, the measured differences with a margin
   of 1.2-3 points;
 - the 8x8x1 -> 16x16x1 step reduces the differences (reaction, w(1,5))
   by at least 2.5x (EOC > 1.3; measured 4.6x and 3.9x).
So a 3D reaction off by +2.2 % or -1.3 % fails the test. The centre must
lie on the obstacle (w(5,5) = -0.995 within 1e-5 for every model) and the
penetration is bounded (Mindlin 1e-5; 3D 2e-4: with 3x3 contact points per
face the nodes between them penetrate by 1e-4, doc/results.md; GSV 1e-3:
the stabilised method lets the cubic dip inside the cells, 3.6e-4 below
the obstacle on 16^2 at its contact points (max_penetration), 3.3e-5 on
32^2, 4.9e-6 on 64^2, while its vertices stay on it; min_deflection
samples the cell interiors).
The contact area is not compared: it is a different quantity in GSV and
in the inserted-kinematics formulations (doc/results.md).
The 3D runs refine in plane (8x8x1 -> 16x16x1, nested iteration, as
parameters/paper_3d.prm does); a cold start on 16x16x1 needed 195 Newton
iterations and 60 s, the nested run about 100 iterations and 10 s."""
import os
import time
from common import parse_args, run, check, close, finish, MINDLIN_GSV

args = parse_args()
PRM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "parameters")
OBSTACLE_W = -0.995        # lowest admissible mid-plane level
CLAMPED_SQUARE = 0.00126532  # w_max D/(q a^4), clamped square plate
E, NU, T, Q, A = 2e5, 0.3, 0.01, 0.02, 10.0
D = E * T ** 3 / (12 * (1 - NU ** 2))


def paper(prm, extra):
    """parameters/<prm> with extra entries appended (later entries win)."""
    return open(os.path.join(PRM, prm)).read() + "\n" + extra + """
subsection Output
  set Probe points = 5, 5; 2.5, 5; 1, 5; 2.5, 2.5
end
"""


def solve_cycles(name, text):
    """All cycles of the run."""
    t0 = time.time()
    s, _ = run(args, name, text)
    check(all(x["converged"] for x in s["cycles"]), "%s converged" % name)
    for c in s["cycles"]:
        print("      %-16s %5d DoFs %3d its %5.1f s: reaction %.6f, w(5,5) %.7f, w(2.5,5) %.6f, "
              "w(1,5) %.6f, w(2.5,2.5) %.6f, min w %.7f"
              % (name, c["n_dofs"], c["nonlinear_iterations"], time.time() - t0,
                 c["contact_force"], *c["probes"], c["min_deflection"]))
    return s["cycles"]


def solve(name, text):
    """The last cycle of the run."""
    return solve_cycles(name, text)[-1]


def mesh3d(n):
    return "subsection Geometry\n  set Subdivisions = %d, %d, 1\n  set Number of cycles = 1\nend\n" % (n, n)


# the 3D mesh's stiffness error, from a published value
free = solve("elasticity_free", paper("paper_3d.prm", mesh3d(16) +
                                      "subsection Obstacle\n  set Level = -1000\nend\n"))
w_exact = CLAMPED_SQUARE * Q * A ** 4 / D
d_free = abs(free["probes"][0]) / w_exact - 1
check(-0.03 <= d_free < 0, "3D 16x16x1 free plate: centre deflection %.5f vs %.5f (Timoshenko): "
      "%.2f %% in [-3 %%, 0) (the mesh is slightly too stiff)"
      % (abs(free["probes"][0]), w_exact, 100 * d_free))

# 8x8x1 -> 16x16x1, nested (paper_3d.prm refines in plane only)
e8, e16 = solve_cycles("elasticity", paper("paper_3d.prm", """
subsection Geometry
  set Subdivisions = 8, 8, 1
  set Number of cycles = 2
end
"""))
check(e16["n_dofs"] == 9801, "3D second cycle is the 16x16x1 Q2 mesh (9801 DoFs): %d" % e16["n_dofs"])
mindlin = solve("mindlin", paper("paper_mindlin.prm", """
subsection Geometry
  set Subdivisions = 8, 8
  set Number of cycles = 3
end
"""))
gsv = solve("kirchhoff", paper("paper_kirchhoff.prm", """
subsection Geometry
  set Subdivisions = 16, 16
  set Number of cycles = 1
end
"""))
# Kirchhoff plate as stiff as the 3D mesh (E scaled by the measured factor)
stiff = solve("kirchhoff_stiff", paper("paper_kirchhoff.prm", """
subsection Geometry
  set Subdivisions = 32, 32
  set Number of cycles = 1
end
subsection Material
  set Young's modulus = %.10g
end
""" % (E / (1 + d_free))))

# plates agree with each other
close(mindlin["contact_force"], gsv["contact_force"], 5e-3, "reaction, Mindlin 32^2 vs GSV 16^2")
close(mindlin["probes"][1], gsv["probes"][1], 5e-3, "w(2.5,5), Mindlin vs GSV")
close(mindlin["probes"][3], gsv["probes"][3], 6e-3, "w(2.5,2.5), Mindlin vs GSV")
close(mindlin["probes"][2], gsv["probes"][2], 3e-2, "w(1,5), Mindlin vs GSV")
# the Mindlin plate's default contact stress ('gsv'), without the bias
mindlin_gsv = solve("mindlin_gsv", paper("paper_mindlin.prm", """
subsection Geometry
  set Subdivisions = 8, 8
  set Number of cycles = 3
end
""" + MINDLIN_GSV))
for j, what, tol in ((None, "reaction", 4.5e-3), (1, "w(2.5,5)", 4.5e-3),
                     (3, "w(2.5,2.5)", 5.5e-3), (2, "w(1,5)", 2.5e-2)):
    value = (lambda c: c["contact_force"] if j is None else c["probes"][j])
    close(value(mindlin_gsv), value(gsv), tol, "%s, Mindlin gsv 32^2 vs GSV 16^2" % what)

# 3D vs plates: bracketed between GSV (minus a tolerance) and the stiffened plate
QUANTITIES = [("reaction", lambda c: c["contact_force"], 0.04),
              ("|w(2.5,5)|", lambda c: abs(c["probes"][1]), 0.02),
              ("|w(2.5,2.5)|", lambda c: abs(c["probes"][3]), 0.04),
              ("|w(1,5)|", lambda c: abs(c["probes"][2]), 0.11)]
for what, f, tol in QUANTITIES:
    d16 = f(e16) / f(gsv) - 1
    d8 = f(e8) / f(gsv) - 1
    upper = f(stiff) / f(gsv) - 1
    check(-tol <= d16 <= upper,
          "3D 16x16x1 vs GSV 16^2, %s: %+.2f %% in [%+.1f %%, %+.2f %% (plate %.2f %% stiffer)]"
          % (what, 100 * d16, -100 * tol, 100 * upper, -100 * d_free))
    if what in ("reaction", "|w(1,5)|"):
        check(abs(d16) * 2.5 <= abs(d8),
              "3D %s: difference to GSV shrinks from %+.2f %% (8x8x1) to %+.2f %% "
              "(16x16x1), factor %.1f >= 2.5" % (what, 100 * d8, 100 * d16, d8 / d16))

for name, c, pen in (("3D", e16, 2e-4), ("Mindlin", mindlin, 1e-5), ("GSV", gsv, 1e-3)):
    check(abs(c["probes"][0] - OBSTACLE_W) <= 1e-5,
          "%s: centre on the obstacle level, w(5,5) = %.8f" % (name, c["probes"][0]))
    check(c["min_deflection"] >= OBSTACLE_W - pen,
          "%s: penetration %.2e <= %.0e" % (name, OBSTACLE_W - c["min_deflection"], pen))
check(gsv["extra"]["max_penetration"] <= 1e-3,
      "GSV: penetration at the contact points %.2e <= 1e-3" % gsv["extra"]["max_penetration"])

# Simply supported edges of the 3D model (u3 = 0 on the lateral faces, the
# in-plane displacements free: the edges rotate and the plate may pull in)
# are the soft simple support of a Reissner-Mindlin plate (w = 0 only),
# whose boundary layer of width ~t makes it softer than Kirchhoff's
# 0.0040623527 q a^4/D. Unit square, t/a = 0.01, D = 1, no contact: the 3D
# model on 16x16x1 Q2 cells against the MITC9 plate with soft support on
# 16^2 cells (the same nodes), within 0.25 % (measured: 3D 0.0040719, MITC9
# 0.0040783, -0.16 %; both still rise under refinement while the layer is
# not resolved, 3D 32x32x1 0.0040838, MITC9 0.0040877 on 32^2), and more
# than 0.1 % above the hard simple support's closed form 0.0040623527 (1 +
# 5.18147 (t/a)^2) = 0.0040645, which a hard support on these nodes gives
# (MITC9 hard: 0.0040645), so that a 3D edge that held the rotation too
# would fail.
SS = """
subsection Geometry
  set Length x = 1
  set Length y = 1
  set Thickness = 0.01
  set Boundary conditions = all: simply supported
  set Subdivisions = %s
end
subsection Material
  set Young's modulus = %.17g
end
subsection Load
  set Transverse load = -1
end
subsection Obstacle
  set Level = -1e10
end
subsection Contact
  set Nitsche theta = 0
end
subsection Elasticity
  set Refine through thickness = false
end
subsection Mindlin
  set Simple support = soft
  set Shear treatment = MITC9
end
subsection Output
  set Probe points = 0.5, 0.5
end
""" % ("%s", 12 * (1 - NU ** 2) / 0.01 ** 3)
ss3d, _ = run(args, "elasticity_ss", "set Model = elasticity\n" + SS % "16, 16, 1")
ssm, _ = run(args, "mindlin_soft_ss", "set Model = mindlin\n" + SS % "16, 16")
w3, wm = -ss3d["cycles"][-1]["probes"][0], -ssm["cycles"][-1]["probes"][0]
close(w3, wm, 2.5e-3, "simply supported 3D 16x16x1 vs soft simply supported MITC9 16^2")
hard = 0.0040623527 * (1 + 5.18147 * 0.01 ** 2)
check(w3 > 1.001 * hard and wm > 1.001 * hard,
      "soft simple supports deflect more than 1.001 x the hard support's %.7f "
      "(3D %.7f, Mindlin %.7f)" % (hard, w3, wm))
finish()
