"""Contact patch test of the 3D elasticity model: an elastic block pressed
uniformly onto a flat rigid obstacle must reproduce the exact uniform
solution to round-off, for theta = 1, 0, -1, frictionless and with Coulomb
friction (F = 0.5), with Q1 and Q2 hexahedra.

Block [0,1]^2 x (-1/2, 1/2), top traction (0, 0, -p), obstacle plane z = -1/2
(gap 0 on the whole bottom face), no body force.

Exact solutions (independent, closed form; sigma_33 = -p everywhere):
- frictionless, symmetry on x = 0 and y = 0, the faces x = 1, y = 1 free:
  uniaxial stress, u1 = nu p x / E, u2 = nu p y / E, u3 = -p (z + 1/2) / E;
- F = 0.5, symmetry on all four lateral faces: uniaxial strain,
  u1 = u2 = 0, u3 = -p (z + 1/2) / (lambda + 2 mu).
Both are linear, hence in the Q1 and Q2 spaces, and Nitsche's method is
consistent: at the bottom face sigma_n = -p, u_n = 0 = g, so the Nitsche
stress Lambda_n = [sigma_n - r (u_n - g)]_- = -p = sigma_n and all theta-terms
cancel; with friction sigma_t = 0 and u_t = 0, so Lambda_t = 0 (stick).
Hence the discrete solution must equal the exact one up to round-off for any
theta, gamma0 and mesh. Checked per run: L2 and H1 errors (from the program's
'Reference solution') relative to the L2 / H1 size of the exact solution,
the nodal error relative to max |u|, all <= 1e-10 (H1: <= 1e-7, because
deal.II's FunctionParser differentiates the exact solution by finite
differences, which alone costs ~3e-9); contact force = p * area
and contact area = 1 to 1e-10; every contact point active; the probe at
(0.5, 0.5) (u3 on the mid-plane) equals -b/2; with friction every contact
point sticks (stick area 1, slip area 0) and |Lambda_t| = 0.

A wrong sign or a missing term in the Nitsche kernel, a wrong h_n in r when
the solution is not exact, a wrong traction or a wrong symmetry condition
shows up as an O(1) relative error here.
"""
import math
import re
from common import parse_args, run, check, finish

args = parse_args()

E, NU, P = 100.0, 0.3, 1.0
LAM = E * NU / ((1 + NU) * (1 - 2 * NU))
MU = E / (2 * (1 + NU))

TEMPLATE = """
set Model = elasticity
subsection Geometry
  set Length x = 1
  set Length y = 1
  set Thickness = 1
  set Boundary conditions = %(edges)s
  set Subdivisions = 3, 2, 2
  set Number of cycles = 1
end
subsection Material
  set Young's modulus = %(E)r
  set Poisson ratio = %(nu)r
end
subsection Load
  set Transverse load = %(q)r
end
subsection Obstacle
  set Type = plane
  set Level = -0.5
end
subsection Contact
  set Nitsche theta = %(theta)d
  set Nitsche gamma0 = %(gamma0)g
  set Friction coefficient = %(F)g
end
subsection Elasticity
  set Polynomial degree = %(degree)d
  set Load applied as = top traction
  set Top face = free
end
subsection Nonlinear solver
  set Scheme = %(scheme)s
  set Tolerance = 1e-13
  set Maximum iterations = 20
end
subsection Output
  set Probe points = 0.5, 0.5
end
subsection Reference solution
  set Exact solution = %(exact)s
  set Function constants = %(constants)s
end
"""

CASES = {
    # name: (edges, exact solution, constants, (a, b)) with u1 = a x,
    # u2 = a y, u3 = -b (z + 1/2)
    "frictionless": ("0: symmetry; 1: free; 2: symmetry; 3: free",
                     "nu*p*x/E; nu*p*y/E; -p*(z+0.5)/E",
                     "E=%r, nu=%r, p=%r" % (E, NU, P),
                     (NU * P / E, P / E)),
    "friction": ("all: symmetry",
                 "0; 0; -p*(z+0.5)/M",
                 "M=%r, p=%r" % (LAM + 2 * MU, P),
                 (0.0, P / (LAM + 2 * MU))),
}

TOL = 1e-10
TOL_H1 = 1e-7
for degree in (1, 2):
    for kind, (edges, exact, constants, (a, b)) in CASES.items():
        # exact norms on the unit block: int x^2 = int (z+1/2)^2 = 1/3
        l2_size = math.sqrt((2 * a * a + b * b) / 3.0)
        h1_size = math.sqrt(2 * a * a + b * b)
        max_u = max(a, b)
        F = 0.5 if kind == "friction" else 0.0
        for theta in (1, 0, -1):
            for scheme in (("newton", "fixed point") if F > 0 else ("newton",)):
                # a small gamma0 for theta = -1 (allowed for any gamma0 > 0)
                gamma0 = 0.1 if theta == -1 else 20
                name = "patch_Q%d_%s_theta%d_%s" % (degree, kind, theta,
                                                    scheme.replace(" ", "_"))
                s, _ = run(args, name, TEMPLATE % dict(
                    edges=edges, E=E, nu=NU, q=-P, theta=theta, gamma0=gamma0,
                    F=F, degree=degree, scheme=scheme, exact=exact,
                    constants=constants))
                c = s["cycles"][-1]
                err = c["errors"]
                tag = "Q%d %s theta=%+d %s:" % (degree, kind, theta, scheme)
                check(c["converged"], tag + " converged in %d iterations"
                      % c["nonlinear_iterations"])
                check(err["L2"] / l2_size <= TOL,
                      tag + " relative L2 error %.2e <= %.0e" % (err["L2"] / l2_size, TOL))
                # deal.II's FunctionParser differentiates the exact solution
                # by finite differences (error ~1e-9): looser bound for H1
                check(err["H1"] / h1_size <= TOL_H1,
                      tag + " relative H1 error %.2e <= %.0e" % (err["H1"] / h1_size, TOL_H1))
                check(err["Linf_nodes"] / max_u <= TOL,
                      tag + " relative nodal error %.2e <= %.0e" % (err["Linf_nodes"] / max_u, TOL))
                check(abs(c["contact_area"] - 1.0) <= TOL,
                      tag + " contact area %.12g == 1" % c["contact_area"])
                check(abs(c["contact_force"] - P * 1.0) <= TOL * P,
                      tag + " contact force %.12g == p * area = %g" % (c["contact_force"], P))
                # the pressure is uniform: its maximum is p as well
                check(abs(c["extra"]["max_contact_pressure"] - P) <= TOL * P,
                      tag + " max contact pressure %.12g == p = %g"
                      % (c["extra"]["max_contact_pressure"], P))
                check(c["active_points"] == c["contact_points"],
                      tag + " all %d contact points active" % c["contact_points"])
                check(abs(c["max_deflection"]) <= TOL * b and
                      abs(c["min_deflection"] + b) <= TOL * b,
                      tag + " u3 in [%.12g, %.3g] == [-%.12g, 0]"
                      % (c["min_deflection"], c["max_deflection"], b))
                # the probe is u3 on the mid-plane z = 0: -b/2
                check(abs(c["probes"][0] + 0.5 * b) <= TOL * b,
                      tag + " probe (0.5, 0.5) on the mid-plane %.12g == -b/2 = %.12g"
                      % (c["probes"][0], -0.5 * b))
                if F > 0:
                    check(c["stick_points"] == c["contact_points"],
                          tag + " all points stick (%d of %d)"
                          % (c["stick_points"], c["contact_points"]))
                    check(c["extra"]["max_friction_ratio"] <= TOL,
                          tag + " |Lambda_t|/|Lambda_n| = %.2e == 0"
                          % c["extra"]["max_friction_ratio"])
                    # the whole face (area 1) sticks
                    check(abs(c["extra"]["stick_area"] - 1.0) <= TOL and
                          c["extra"]["slip_area"] == 0.,
                          tag + " stick area %.12g == 1, slip area %g == 0"
                          % (c["extra"]["stick_area"], c["extra"]["slip_area"]))

# In-plane refinement ('Refine through thickness = false'): the nested start
# carried to the next mesh by evaluation at its support points must be the
# exact interpolant. The exact solution is linear, hence the same function on
# both meshes: the first Newton correction of the refined cycle must vanish
# (a wrong transfer gives |dU|_a/|U|_a of order one), and both cycles must
# reproduce the exact solution. With 'Initial refinement = 1' (2 x 2 layers
# through the thickness), Q1 and Q2, on 1 and 2 MPI ranks.
edges, exact, constants, (a, b) = CASES["frictionless"]
l2_size = math.sqrt((2 * a * a + b * b) / 3.0)
for degree, np in ((1, 1), (2, 1), (2, 2)):
    text = TEMPLATE % dict(edges=edges, E=E, nu=NU, q=-P, theta=1, gamma0=20, F=0.0,
                           degree=degree, scheme="newton", exact=exact,
                           constants=constants)
    text += """
subsection Geometry
  set Initial refinement = 1
  set Number of cycles = 2
end
subsection Elasticity
  set Refine through thickness = false
end
subsection Nonlinear solver
  set Print iterations = true
end
"""
    tag = "in-plane refinement, Q%d, %d rank(s):" % (degree, np)
    s, log = run(args, "patch_inplane_Q%d_np%d" % (degree, np), text, np=np)
    cycles = s["cycles"]
    check([c["n_dofs"] for c in cycles] == [3 * (3 * 2 * degree + 1) * (2 * 2 * degree + 1) * (2 * 2 * degree + 1),
                                          3 * (6 * 2 * degree + 1) * (4 * 2 * degree + 1) * (2 * 2 * degree + 1)],
          tag + " DoFs %s: 6x4x4 -> 12x8x4 cells" % [c["n_dofs"] for c in cycles])
    for c in cycles:
        check(c["converged"] and c["errors"]["L2"] / l2_size <= TOL,
              tag + " cycle %d: relative L2 error %.2e <= %.0e"
              % (c["cycle"], c["errors"]["L2"] / l2_size, TOL))
    first = re.search(r"Cycle 1:.*?iteration +1:.*?\|dU\|_a/\|U\|_a ([0-9.e+-]+)", log, re.S)
    du = float(first.group(1)) if first else float("inf")
    check(du <= 1e-8, tag + " first Newton correction after the transfer "
          "|dU|_a/|U|_a = %.1e <= 1e-8" % du)
finish()
