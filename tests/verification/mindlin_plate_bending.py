"""Reissner-Mindlin plate without contact (MITC4 and MITC9): clamped and hard
simply supported unit square under a uniform load, t/a = 0.1, 0.01, 0.001.

Independent sources (doc/theory.md section 6.2):
- raw MITC4 centre deflections w_c D/(q a^4) on a uniform 32x32 mesh from an
  independent numpy prototype (digit-by-digit check of the element);
- hard simple support, closed form (Marcus splitting):
  w_c D/(q a^4) = 0.00406235 (1 + 5.18147 (t/a)^2);
- no locking: clamped, t/a = 0.001, 32x32 within 0.1 % of Kirchhoff's
  0.00126532; plain Q1 shear ('Shear treatment = full') must lock there;
- theta-terms of the literal insertion act on the whole plate: for theta =
  +-1 the bending stiffness of div(phi)^2 drops by c = theta lambda^2 eps^2 / r,
  i.e. D -> D - c for a hard simply supported plate (whose Kirchhoff deflection
  depends on D only), so w_c = 0.00406235 D/(D - c) + shear part.
- MITC9 (Q2, Bucalem-Bathe): the hard simple support closed form on 16x16
  cells to 2e-5 (measured: 6.3e-6 to 6.6e-6),
  the clamped t/a = 0.001 deflection within 1e-4 of Kirchhoff's, and the
  exact solution below with the rates 3, 2, 3, 2 at t/a = 0.1 and 0.001
  (no locking in the rates either).
- the error norms: with no load (zero solution) against a polynomial
  reference, the reported L2/H1 errors of w and phi are its norms in
  closed form (1e-7), MITC4 and MITC9.
The obstacle is placed far below (no contact); theta = 0 except in the last
check. E = 12 (1 - nu^2) / t^3 gives D = 1, a = 1, q = 1."""
from common import parse_args, run, check, close, finish, first_corrections

args = parse_args()
nu = 0.3

TEMPLATE = """
set Model = mindlin
subsection Geometry
  set Length x = 1
  set Length y = 1
  set Thickness = %(t)g
  set Boundary conditions = all: %(bc)s
  set Subdivisions = %(n)d, %(n)d
end
subsection Material
  set Young's modulus = %(E).17g
  set Poisson ratio = 0.3
end
subsection Load
  set Transverse load = -1
end
subsection Obstacle
  set Level = -1e10
end
subsection Contact
  set Nitsche theta = %(theta)d
end
subsection Mindlin
  set Shear treatment = %(shear)s
end
subsection Output
  set Probe points = 0.5, 0.5
end
"""


def centre(name, t, bc, n=32, theta=0, shear="MITC4"):
    E = 12 * (1 - nu * nu) / t ** 3
    s, _ = run(args, name, TEMPLATE % dict(t=t, bc=bc, n=n, E=E, theta=theta,
                                          shear=shear))
    c = s["cycles"][-1]
    check(c["converged"] and c["contact_area"] == 0.0,
          "%s: converged without contact" % name)
    return -c["probes"][0]


# Raw MITC4 values at n = 32 (doc/theory.md table 6.2, independent prototype).
table = {("clamped", 0.1): 0.00150355, ("clamped", 0.01): 0.00126692,
         ("clamped", 0.001): 0.00126442,
         ("simply supported", 0.1): 0.00427173,
         ("simply supported", 0.01): 0.00406318,
         ("simply supported", 0.001): 0.00406109}
values = {}
for (bc, t), ref in table.items():
    name = "mindlin_%s_%g" % ("ss" if bc.startswith("s") else "cl", t)
    values[(bc, t)] = centre(name, t, bc)
    # 6 significant digits in the table
    close(values[(bc, t)], ref, 2e-5, "%s t/a=%g raw MITC4 32x32" % (bc, t))

# Hard simple support against the closed form; 32x32 is O(h^2) = 3e-4 off.
for t in (0.1, 0.01, 0.001):
    exact = 0.00406235 * (1 + 5.18147 * t * t)
    close(values[("simply supported", t)], exact, 5e-4,
          "hard SS t/a=%g vs closed form" % t)

# No locking (MITC4) and locking of the plain Q1 shear.
kirchhoff = 0.00126532
close(values[("clamped", 0.001)], kirchhoff, 1e-3,
      "clamped t/a=0.001 within 0.1 percent of Kirchhoff")
locked = centre("mindlin_cl_full", 0.001, "clamped", shear="full")
check(locked < 0.5 * kirchhoff,
      "plain Q1 shear locks: w_c = %.4g < 0.5 x Kirchhoff" % locked)

# theta = +-1: the global effect of the theta-terms (doc/mindlin.md).
t = 0.1
lam_over_E = nu / ((1 + nu) * (1 - 2 * nu))
c_over_D = 3 * (1 - nu * nu) * lam_over_E ** 2 / 20.0   # gamma0 = 20
shear_part = 0.00406235 * 5.18147 * t * t
discretisation = values[("simply supported", t)] - 0.00406235 * (1 + 5.18147 * t * t)
for theta in (1, -1):
    w = centre("mindlin_ss_theta%d" % theta, t, "simply supported", theta=theta)
    predicted = 0.00406235 / (1 - theta * c_over_D) + shear_part + discretisation
    close(w, predicted, 2e-4,
          "hard SS t/a=0.1, theta=%d: w_c = w_K D/(D - theta c) + shear" % theta)

# Exact solution (hard SS, load q = -sin(pi x) sin(pi y), Marcus splitting):
# w = -(1/(4 pi^4 D) + 1/(2 pi^2 kappa mu t)) sin sin, phi = -grad w_K with
# w_K the Kirchhoff part. MITC4 must converge at the optimal rates:
# L2(w), L2(phi) ~ h^2 and H1(w), H1(phi) ~ h; MITC9 one order higher.
import math


def exact_solution_run(name, t, shear, subdivisions):
    E = 12 * (1 - nu * nu) / t ** 3
    mu = E / (2 * (1 + nu))
    A = 1 / (4 * math.pi ** 4) + 1 / (2 * math.pi ** 2 * (5 / 6) * mu * t)
    B = 1 / (4 * math.pi ** 3)
    s, log = run(args, name, """
set Model = mindlin
subsection Geometry
  set Length x = 1
  set Length y = 1
  set Thickness = %g
  set Boundary conditions = all: simply supported
  set Subdivisions = %d, %d
  set Number of cycles = 4
end
subsection Material
  set Young's modulus = %.17g
end
subsection Load
  set Transverse load = -sin(pi*x)*sin(pi*y)
end
subsection Obstacle
  set Level = -1e10
end
subsection Contact
  set Nitsche theta = 0
end
subsection Mindlin
  set Shear treatment = %s
end
subsection Reference solution
  set Exact solution = -A*sin(pi*x)*sin(pi*y); B*cos(pi*x)*sin(pi*y); B*sin(pi*x)*cos(pi*y)
  set Function constants = A=%.17g, B=%.17g
end
subsection Output
  set Probe points = 0.5, 0.5
end
""" % (t, subdivisions, subdivisions, E, shear, A, B))
    return s, log, A


s, log, A = exact_solution_run("mindlin_exact", 0.1, "MITC4", 4)
# nested iteration (no contact here: a linear problem): each cycle starts
# from the previous cycle's solution carried onto the refined mesh, so its
# first correction is the change of the discrete solution between the two
# meshes, which halves from cycle to cycle like the energy-norm error (rate
# 1). From U = 0 it would be 1 on every cycle.
firsts = first_corrections(log)
check(len(firsts) == 4 and all(0.4 < firsts[k + 1] / firsts[k] < 0.6 for k in range(1, 3))
      and firsts[1] < 0.9,
      "exact solution: first corrections of the nested cycles %s halve per cycle"
      % ", ".join("%.3e" % f for f in firsts[1:]))
c = s["cycles"][-1]
for name, rate in (("L2(w)", 2), ("H1(w)", 1), ("L2(phi)", 2), ("H1(phi)", 1)):
    got = c["rates"][name]
    check(abs(got - rate) < 0.1, "exact solution: rate of %s = %.3f (expected %d)"
          % (name, got, rate))
close(-c["probes"][0], A, 2e-3, "exact solution: centre deflection")

# MITC9: the same solution, t/a = 0.1 and 0.001, 2x2 -> 16x16 cells.
for t in (0.1, 0.001):
    s, _, A = exact_solution_run("mindlin_exact_mitc9_%g" % t, t, "MITC9", 2)
    c = s["cycles"][-1]
    for name, rate in (("L2(w)", 3), ("H1(w)", 2), ("L2(phi)", 3), ("H1(phi)", 2)):
        got = c["rates"][name]
        check(abs(got - rate) < 0.1, "MITC9 exact solution t/a=%g: rate of %s = "
              "%.3f (expected %d)" % (t, name, got, rate))
    close(-c["probes"][0], A, 1e-5, "MITC9 exact solution t/a=%g: centre "
          "deflection" % t)

# The error norms themselves: with no load the discrete solution is exactly
# zero, so against the reference (w, phi_x, phi_y) = (a x y, b x^2, c x y)
# on [0,1] x [0,2] the reported errors are the norms of that polynomial,
# in closed form (the rates above cannot see a wrong component or a
# missing term in a norm).
a, b, c, Lx, Ly = 0.3, -0.7, 1.1, 1.0, 2.0


def monomial(px, py):
    """integral of x^px y^py over [0,Lx] x [0,Ly]"""
    return Lx ** (px + 1) / (px + 1) * Ly ** (py + 1) / (py + 1)


norms = {"L2(w)": math.sqrt(a * a * monomial(2, 2)),
         "H1(w)": math.sqrt(a * a * (monomial(0, 2) + monomial(2, 0))),
         "L2(phi)": math.sqrt(b * b * monomial(4, 0) + c * c * monomial(2, 2)),
         "H1(phi)": math.sqrt(4 * b * b * monomial(2, 0)
                              + c * c * (monomial(0, 2) + monomial(2, 0)))}
for shear in ("MITC4", "MITC9"):
    s, _ = run(args, "mindlin_error_norms_" + shear, """
set Model = mindlin
subsection Geometry
  set Length x = 1
  set Length y = 2
  set Thickness = 0.1
  set Boundary conditions = all: clamped
  set Subdivisions = 3, 4
end
subsection Load
  set Transverse load = 0
end
subsection Obstacle
  set Level = -1e10
end
subsection Mindlin
  set Shear treatment = %s
end
subsection Reference solution
  set Exact solution = a*x*y; b*x*x; c*x*y
  set Function constants = a=%r, b=%r, c=%r
end
""" % (shear, a, b, c))
    errors = s["cycles"][-1]["errors"]
    for name, value in norms.items():
        # (the exact gradients come from FunctionParser's finite differences)
        close(errors[name], value, 1e-7,
              "%s, zero solution: error %s = the norm of the reference" % (shear, name))

# MITC9 against the closed form (hard SS) and Kirchhoff (clamped, thin).
for t in (0.1, 0.01, 0.001):
    w = centre("mindlin9_ss_%g" % t, t, "simply supported", n=16, shear="MITC9")
    close(w, 0.00406235 * (1 + 5.18147 * t * t), 2e-5,
          "MITC9 16x16 hard SS t/a=%g vs closed form" % t)
w = centre("mindlin9_cl_0.001", 0.001, "clamped", n=16, shear="MITC9")
close(w, kirchhoff, 1e-4, "MITC9 16x16 clamped t/a=0.001 within 1e-4 of Kirchhoff")
finish()
