"""Clamped strip (cylindrical bending) on a flat obstacle, solved as a
Reissner-Mindlin plate with both contact formulations (doc/theory.md 4.8,
doc/mindlin.md).

Exact Kirchhoff solution for the paper's data (L = 10, t = 0.01, E = 2e5,
nu = 0.3, q = 0.02, obstacle 1 below the mid-plane, i.e. g0 = 1 - t/2):
  l = (72 D g0 / q)^(1/4),  w(x) = -q x^4/(24D) + q l x^3/(9D) - q l^2 x^2/(12D)
  on [0, l] (mirrored), w = -g0 on [l, L-l], total reaction q (L - 4l/3).
Differences expected between the Mindlin/Nitsche solution and this:
  - discretisation, O(h^2) in w (h = 0.0625 here: about 2e-4 relative);
  - shear deformation, O((t/l)^2) = 1e-5;
  - the Nitsche penalty: penetration q/r = 5e-11 (r = gamma0 E / t = 4e8;
    'gsv': r = gamma0 kappa_s mu t / h^2 ~ 1e7, q/r ~ 2e-9)
    and the Poisson-stress shift |sigma_n|/r = O(eps^2 |k|/gamma0) < 1e-8;
  so deflections are checked to 1e-3, the reaction to 2e-4 (measured:
  2e-5 to 6e-5) and the flat zone to 1e-8. The contact area (points with Lambda_n < 0) converges slowly: the
  plate approaches the obstacle with a cubic tangency, w + g0 ~ (q l/(18 D))
  (l - x)^3 (w'' = 0 at l), so an O(h^2) error in w moves the discrete free
  boundary by O(h^(2/3)) ~ 0.1-0.3; it is checked to lie in [L - 2l - 0.8,
  L - 2l + 0.05].

'Contact formulation = nitsche' (the paper's form): with theta = 1 the
theta-term -(1/r) lambda^2 eps^2 (phi_x', chi_x') acts on the whole strip
(doc/mindlin.md): the exact solution is then the strip with D' = D - c,
c = lambda^2 eps^2 / r, which is checked as well. The theta = 1 case is also
run with the 2x2 Gauss-Lobatto (vertex) contact rule ('Contact quadrature
rule = lobatto'), against the same solution, and both theta = 1 cases again
with the MITC9 element (Q2) on half the cells, i.e. the same nodes along the
strip: its largest probe error must be at most 0.3 of MITC4's (measured:
0.12 with the Gauss points, 0.21 with Lobatto, whose 3x3 points are the Q2
nodes).

'Contact formulation = gsv': the normal stress is the plate's transverse
equilibrium sigma_n = f + div Q_h, so theta = 1, 0 and -1 all converge to the
strip with the plate's stiffness D, with gamma0 = auto. It is run on two
elements whose div Q_h does not vanish cell by cell: MITC9 on the uniform
mesh (8 cells, 3x3 Gauss-Lobatto points) and MITC4 on a mesh file of
trapezoids (16 cells, every inner top vertex moved by 0.3 h, 4x4 Gauss
points). Besides the checks above (D - c would miss the probes by 1e-2),
the largest probe error must fall by at least 2.5 between the first cycle
and the last two (no plateau)."""
import os
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
  %(geometry)s
  set Thickness = 0.01
  set Boundary conditions = 0: clamped; 1: clamped; 2: symmetry; 3: symmetry
  set Number of cycles = 5
end
subsection Load
  set Transverse load = -0.02
end
subsection Obstacle
  set Level = -1
end
subsection Contact
  set Nitsche theta = %(theta)d
  set Nitsche gamma0 = %(gamma0)s
end
subsection Nonlinear solver
  set Tolerance = 1e-8
  set Maximum iterations = 200
end
subsection Mindlin
  set Contact formulation = %(formulation)s
  set Shear treatment = %(shear)s
  set Contact quadrature points = %(points)d
  set Contact quadrature rule = %(rule)s
end
subsection Output
  set Probe points = 1, 0.5; 2, 0.5; 2.5, 0.5; 5, 0.5
end
"""


def write_trapezoid_mesh(path, n):
    """n trapezoids along [0, L] x [0, H] (UCD); boundary ids 0 (x = 0),
    1 (x = L), 2 (y = 0), 3 (y = H)."""
    h = L / n
    nodes = [(i * h, 0.0) for i in range(n + 1)]
    nodes += [(i * h + (0.3 * h * (-1) ** i if 0 < i < n else 0.0), H)
              for i in range(n + 1)]
    cells = ["%d 0 quad %d %d %d %d" % (i + 1, i + 1, i + 2, n + i + 3, n + i + 2)
             for i in range(n)]
    lines = [(0, 1, n + 2), (1, n + 1, 2 * n + 2)]
    lines += [(2, i + 1, i + 2) for i in range(n)]
    lines += [(3, n + i + 2, n + i + 3) for i in range(n)]
    cells += ["%d %d line %d %d" % (n + 1 + k, b, a, c)
              for k, (b, a, c) in enumerate(lines)]
    with open(path, "w") as f:
        f.write("%d %d 0 0 0\n" % (len(nodes), len(cells)))
        for k, (x, y) in enumerate(nodes):
            f.write("%d %.17g %.17g 0\n" % (k + 1, x, y))
        f.write("\n".join(cells) + "\n")


def strip(D):
    l = (72 * D * g0 / q) ** 0.25
    w = lambda x: -q * x ** 4 / (24 * D) + q * l * x ** 3 / (9 * D) \
        - q * l * l * x * x / (12 * D)
    return l, w


def uniform(cells):
    return "set Length x = 10\n  set Length y = 1\n  set Subdivisions = %d, 1" % cells


os.makedirs(args.workdir, exist_ok=True)
mesh = os.path.join(args.workdir, "strip_trapezoids.ucd")
write_trapezoid_mesh(mesh, 16)
trapezoids = "set Shape = mesh file\n  set Mesh file = %s" % mesh

D1 = D0 - lam ** 2 * (t / 2) ** 2 / r
# (name, formulation, theta, stiffness of the limit, geometry, element,
# contact points, rule); MITC9 on half the cells: the same nodes
CASES = [("theta0", "nitsche", 0, D0, uniform(16), "MITC4", 4, "gauss"),
         ("theta1", "nitsche", 1, D1, uniform(16), "MITC4", 4, "gauss"),
         ("theta1_lobatto", "nitsche", 1, D1, uniform(16), "MITC4", 2, "lobatto"),
         ("theta1_mitc9", "nitsche", 1, D1, uniform(8), "MITC9", 4, "gauss"),
         ("theta1_lobatto_mitc9", "nitsche", 1, D1, uniform(8), "MITC9", 3, "lobatto")]
for theta, label in ((1, "1"), (0, "0"), (-1, "_minus1")):
    CASES += [("gsv_mitc9_theta" + label, "gsv", theta, D0, uniform(8), "MITC9", 3, "lobatto"),
              ("gsv_mitc4_trapezoids_theta" + label, "gsv", theta, D0, trapezoids,
               "MITC4", 4, "gauss")]

errors = {}
for case, formulation, theta, D, geometry, shear, n, rule in CASES:
    name = "mindlin_strip_" + case
    s, _ = run(args, name, TEMPLATE % dict(
        geometry=geometry, theta=theta, formulation=formulation, shear=shear,
        points=n, rule=rule, gamma0="auto" if formulation == "gsv" else "20"))
    check(all(x["converged"] for x in s["cycles"]), name + ": all cycles converged")
    c = s["cycles"][-1]
    l, w = strip(D)
    for k, x in enumerate((1.0, 2.0, 2.5)):
        close(c["probes"][k], w(x), 1e-3, "%s: w(%g)" % (name, x))
    per_cycle = [max(abs(cy["probes"][k] - w(x)) / abs(w(x))
                     for k, x in enumerate((1.0, 2.0, 2.5))) for cy in s["cycles"]]
    errors[case] = per_cycle[-1]
    print("%s: largest relative probe error per cycle %s"
          % (name, " ".join("%.3e" % e for e in per_cycle)))
    check(abs(c["probes"][3] + g0) < 1e-8,
          "%s: flat zone w(5) = %.12g = -g0 to 1e-8" % (name, c["probes"][3]))
    close(c["contact_force"] / H, q * (L - 4 * l / 3), 2e-4,
          "%s: total reaction q (L - 4l/3)" % name)
    area = c["contact_area"] / H
    check(L - 2 * l - 0.8 <= area <= L - 2 * l + 0.05,
          "%s: contact length %.4f in [L-2l-0.8, L-2l+0.05] (L-2l = %.4f)"
          % (name, area, L - 2 * l))
    if formulation == "gsv":
        check(max(per_cycle[-2:]) * 2.5 <= per_cycle[0],
              "%s: the probe error falls under refinement (%.3e -> %.3e)"
              % (name, per_cycle[0], max(per_cycle[-2:])))
for rule in ("", "_lobatto"):
    a = errors["theta1%s_mitc9" % rule]
    b = errors["theta1%s" % rule]
    check(a <= 0.3 * b, "MITC9%s on the same nodes: probe error %.3e <= 0.3 x "
          "MITC4's %.3e" % (rule.replace("_", " "), a, b))
finish()
