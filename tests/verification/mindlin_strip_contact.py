"""Clamped strip (cylindrical bending) on a flat obstacle, solved as a
Reissner-Mindlin plate with the literal Nitsche insertion (doc/theory.md 4.8).

Exact Kirchhoff solution for the paper's data (L = 10, t = 0.01, E = 2e5,
nu = 0.3, q = 0.02, obstacle 1 below the mid-plane, i.e. g0 = 1 - t/2):
  l = (72 D g0 / q)^(1/4),  w(x) = -q x^4/(24D) + q l x^3/(9D) - q l^2 x^2/(12D)
  on [0, l] (mirrored), w = -g0 on [l, L-l], total reaction q (L - 4l/3).
Differences expected between the Mindlin/Nitsche solution and this:
  - discretisation, O(h^2) in w (h = 0.0625 here: about 2e-4 relative);
  - shear deformation, O((t/l)^2) = 1e-5;
  - the Nitsche penalty: penetration q/r = 5e-11 (r = gamma0 E / t = 4e8)
    and the Poisson-stress shift |sigma_n|/r = O(eps^2 |k|/gamma0) < 1e-8;
  so deflections are checked to 1e-3, the reaction to 2e-4 (measured:
  2e-5 to 6e-5) and the flat zone to 1e-8. The contact area (points with Lambda_n < 0) converges slowly: the
  plate approaches the obstacle with a cubic tangency, w + g0 ~ (q l/(18 D))
  (l - x)^3 (w'' = 0 at l), so an O(h^2) error in w moves the discrete free
  boundary by O(h^(2/3)) ~ 0.1-0.3; it is checked to lie in [L - 2l - 0.8,
  L - 2l + 0.05].
With theta = 1 the theta-term -(1/r) lambda^2 eps^2 (phi_x', chi_x') acts on
the whole strip (doc/mindlin.md): the exact solution is then the strip with
D' = D - c, c = lambda^2 eps^2 / r, which is checked as well.
The theta = 1 case is also run with the 2x2 Gauss-Lobatto (vertex) contact
rule ('Contact quadrature rule = lobatto'), against the same solution, and
both theta = 1 cases again with the MITC9 element (Q2) on half the cells,
i.e. the same nodes along the strip: its largest probe error must be at most
0.3 of MITC4's (measured: 0.12 with the Gauss points, 0.21 with Lobatto,
whose 3x3 points are the Q2 nodes)."""
from common import parse_args, run, check, close, finish

args = parse_args()
L, H, t, E, nu, q = 10.0, 1.0, 0.01, 2e5, 0.3, 0.02
g0 = 1 - t / 2
D0 = E * t ** 3 / (12 * (1 - nu ** 2))
lam = E * nu / ((1 + nu) * (1 - 2 * nu))
r = 20 * E / t

TEMPLATE = """
set Model = mindlin
subsection Geometry
  set Length x = 10
  set Length y = 1
  set Thickness = 0.01
  set Boundary conditions = 0: clamped; 1: clamped; 2: symmetry; 3: symmetry
  set Subdivisions = %d, 1
  set Number of cycles = 5
end
subsection Load
  set Transverse load = -0.02
end
subsection Obstacle
  set Level = -1
end
subsection Contact
  set Nitsche theta = %d
end
subsection Nonlinear solver
  set Tolerance = 1e-8
  set Maximum iterations = 200
end
subsection Mindlin
  set Shear treatment = %s
  set Contact quadrature points = %d
  set Contact quadrature rule = %s
end
subsection Output
  set Probe points = 1, 0.5; 2, 0.5; 2.5, 0.5; 5, 0.5
end
"""


def strip(D):
    l = (72 * D * g0 / q) ** 0.25
    w = lambda x: -q * x ** 4 / (24 * D) + q * l * x ** 3 / (9 * D) \
        - q * l * l * x * x / (12 * D)
    return l, w


D1 = D0 - lam ** 2 * (t / 2) ** 2 / r
errors = {}
for theta, D, n, rule, shear in ((0, D0, 4, "gauss", "MITC4"),
                                 (1, D1, 4, "gauss", "MITC4"),
                                 (1, D1, 2, "lobatto", "MITC4"),
                                 (1, D1, 4, "gauss", "MITC9"),
                                 (1, D1, 3, "lobatto", "MITC9")):
    name = "mindlin_strip_theta%d%s%s" % (
        theta, "_lobatto" if rule == "lobatto" else "",
        "_mitc9" if shear == "MITC9" else "")
    # MITC9 on half the cells: the same nodes along the strip
    cells = 8 if shear == "MITC9" else 16
    s, _ = run(args, name, TEMPLATE % (cells, theta, shear, n, rule))
    c = s["cycles"][-1]
    check(all(x["converged"] for x in s["cycles"]), name + ": all cycles converged")
    l, w = strip(D)
    for k, x in enumerate((1.0, 2.0, 2.5)):
        close(c["probes"][k], w(x), 1e-3, "%s: w(%g)" % (name, x))
    errors[name] = max(abs(c["probes"][k] - w(x)) / abs(w(x))
                       for k, x in enumerate((1.0, 2.0, 2.5)))
    print("%s: largest relative probe error %.3e" % (name, errors[name]))
    check(abs(c["probes"][3] + g0) < 1e-8,
          "%s: flat zone w(5) = %.12g = -g0 to 1e-8" % (name, c["probes"][3]))
    close(c["contact_force"] / H, q * (L - 4 * l / 3), 2e-4,
          "%s: total reaction q (L - 4l/3)" % name)
    area = c["contact_area"] / H
    check(L - 2 * l - 0.8 <= area <= L - 2 * l + 0.05,
          "%s: contact length %.4f in [L-2l-0.8, L-2l+0.05] (L-2l = %.4f)"
          % (name, area, L - 2 * l))
for rule in ("", "_lobatto"):
    a = errors["mindlin_strip_theta1%s_mitc9" % rule]
    b = errors["mindlin_strip_theta1%s" % rule]
    check(a <= 0.3 * b, "MITC9%s on the same nodes: probe error %.3e <= 0.3 x "
          "MITC4's %.3e" % (rule.replace("_", " "), a, b))
finish()
