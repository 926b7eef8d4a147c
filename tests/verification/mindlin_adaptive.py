"""The Mindlin plate's error estimator and its adaptive cycles
('Contact formulation = gsv', rigid obstacle).

1. Hanging nodes: a plate simply supported on x = 0, free elsewhere,
   pressed by a uniform load onto the plane z = -t/2 + b x that rises from
   the support (the flat plate starts in it) lies on it, w = b x, phi =
   (-b, 0), with no shear, no moment and the pressure q; the gsv contact
   stress is consistent, so MITC4 and MITC9 reproduce it on adapted meshes
   (hanging nodes, chains of them) to round-off, and the estimate is
   round-off too.
2. The estimate is an estimate: the clamped strip on a flat obstacle in
   cylindrical bending, solved in closed form as a Timoshenko beam
   (below): with MITC4 at t/L = 1e-1, 1e-2, 1e-3 and 1e-4, adaptive cycles,
   the effectivity eta / |e|_a lies in [0.3, 10] on every cycle and its
   spread is at most a factor 3; the same for MITC9 for t/L >= 1e-3 (at
   1e-4 its effectivity is printed and kept below 20). The estimate
   without its contact terms is printed beside the error.
3. Adaptive beats uniform: with MITC9 (t/L = 1e-3) the free boundary,
   where the contact pressure concentrates into a layer of width ~t,
   limits the uniform rate; the adaptive rate fitted over the last cycles
   is at least the optimal 1 - 0.1 and at least 0.15 above the uniform
   one (printed: the DoFs at which it reaches the finest uniform error).
4. The same problem, two strategies: parameters/paper_mindlin_adaptive.prm
   (the paper's test, MITC9, to a 5 % estimate) and the uniform cycles of
   its first mesh to 32^2 cells: their reactions differ relatively by at
   most the adaptive run's relative estimate.

The strip (width 0.625, symmetry edges y = 0 and y = 0.625, clamped at x =
0 and x = L = 10, load -q, bottom face on the plane 1 below it): on the
free part [0, l] the shear force is Q = Q0 + q x, D phi'' = Q, w' = Q / S -
phi; on the contact zone w = -1, Q = S phi, D phi'' = S phi, so phi =
phi_l sinh((x - L/2)/d) / sinh((l - L/2)/d), d = (D/S)^(1/2); phi, phi'
and Q are continuous at l, and w(l) = -1 fixes l. The pressure q - S phi'
is positive on the zone and w > -1 on [0, l), so this is the solution."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, finish, shipped_prm

args = parse_args()
L, E, NU, G0 = 10.0, 2e5, 0.3, 1.0
KAPPA = 5.0 / 6.0


def solve3(A, b):
    """Gaussian elimination with pivoting (3 x 3)."""
    M = [row[:] + [v] for row, v in zip(A, b)]
    for i in range(3):
        p = max(range(i, 3), key=lambda r: abs(M[r][i]))
        M[i], M[p] = M[p], M[i]
        for r in range(3):
            if r != i:
                f = M[r][i] / M[i][i]
                M[r] = [x - f * y for x, y in zip(M[r], M[i])]
    return [M[i][3] / M[i][i] for i in range(3)]


def timoshenko_strip(t, q):
    """(exact 'w; phi_x; phi_y' expression, l) of the strip above."""
    D = E * t ** 3 / (12 * (1 - NU ** 2))
    S = KAPPA * E / (2 * (1 + NU)) * t
    d = math.sqrt(D / S)

    def coefficients(l):
        # unknowns Q0, a (phi = (Q0 x^2/2 + q x^3/6)/D + a x) and phi_l;
        # phi'(l+) = phi_l coth((l - L/2)/d) / d
        coth = 1.0 / math.tanh((l - L / 2) / d)
        return solve3([[l * l / (2 * D), l, -1.0], [l / D, 1.0, -coth / d],
                       [1.0, 0.0, -S]],
                      [-q * l ** 3 / (6 * D), -q * l * l / (2 * D), -q * l])

    def w(l, x):
        Q0, a, _ = coefficients(l)
        return (Q0 * x + q * x * x / 2) / S - (Q0 * x ** 3 / 6 + q * x ** 4 / 24) / D - a * x * x / 2

    lo, hi = 1e-6, L / 2 - 1e-9
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (w(lo, lo) + G0) * (w(mid, mid) + G0) <= 0:
            hi = mid
        else:
            lo = mid
    l = 0.5 * (lo + hi)
    Q0, a, phi_l = coefficients(l)
    check(all(w(l, x) > -G0 for x in [k * l / 100 for k in range(100)]),
          "t = %g: the exact strip stays above the obstacle on [0, l)" % t)
    s = "min(min(x, %r - x), %r)" % (L, l)
    S_ = "max(min(x, %r - x), %r)" % (L, l)
    decay = ("exp(-((%s) - %r)/%r)*(1 - exp(-2*(%r - (%s))/%r))/(1 - exp(-2*(%r - %r)/%r))"
             % (S_, l, d, L / 2, S_, d, L / 2, l, d))
    w_expr = ("((%r)*(%s) + %r*(%s)^2)/%r - ((%r)*(%s)^3 + %r*(%s)^4)/%r - %r*(%s)^2"
              % (Q0, s, q / 2, s, S, Q0 / 6, s, q / 24, s, D, a / 2, s))
    phi_expr = ("sign(%r - x)*(((%r)*(%s)^2 + %r*(%s)^3)/%r + (%r)*(%s) + %r*((%s) - 1))"
                % (L / 2, Q0 / 2, s, q / 6, s, D, a, s, phi_l, decay))
    return "%s; %s; 0" % (w_expr, phi_expr), l


def mindlin_prm(geometry, t, q, shear, cycles, refinement, obstacle, exact,
                edges, fraction=0.3):
    return """set Model = mindlin
subsection Geometry
  %s
  set Thickness = %r
  set Boundary conditions = %s
  set Number of cycles = %d
  set Refinement = %s
  set Bulk fraction = %g
end
subsection Load
  set Transverse load = %r
end
subsection Obstacle
  %s
end
subsection Mindlin
  set Shear treatment = %s
end
subsection Nonlinear solver
  set Maximum iterations = 200
end
subsection Reference solution
  set Exact solution = %s
end
""" % (geometry, t, edges, cycles, refinement, fraction, -q, obstacle, shear, exact)


def fitted_rate(cycles, key):
    """Least-squares slope s of log e = c - s log N over `cycles`."""
    xs = [math.log(c["n_dofs"]) for c in cycles]
    ys = [math.log(key(c)) for c in cycles]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


# ---- 1. the tilted plane on meshes with hanging nodes
t, q, b = 0.05, 3.0, 0.03
for shear in ("MITC4", "MITC9"):
    s, _ = run(args, "patch_" + shear, mindlin_prm(
        "set Length x = 2\n  set Length y = 1\n  set Subdivisions = 4, 2", t, q, shear, 4,
        "adaptive", "set Type = function\n  set Height = %r + %r*x" % (-t / 2, b),
        "%r*x; %r; 0" % (b, -b),
        "0: simply supported; 1: free; 2: free; 3: free", fraction=0.5), pinned="rigid")
    for cy in s["cycles"]:
        e = cy["errors"]
        # (H1(w) rests on the exact solution's difference quotients)
        check(e["L2(w)"] <= 1e-11 and e["H1(w)"] <= 1e-9 and e["H1(phi)"] <= 1e-9,
              "%s patch cycle %d (%d cells): L2(w) %.1e, H1(w) %.1e, H1(phi) %.1e at round-off"
              % (shear, cy["cycle"], cy["n_cells"], e["L2(w)"], e["H1(w)"], e["H1(phi)"]))
        # the plate is not strained (|U|_a = 0): eta against the root of
        # the load's work q |Omega| b L_x
        scale = math.sqrt(q * 2.0 * b * 2.0)
        check(cy["error_estimate"] <= 1e-7 * scale,
              "%s patch cycle %d: eta = %.1e at round-off (%.1e of the load's work)"
              % (shear, cy["cycle"], cy["error_estimate"], cy["error_estimate"] / scale))
    cells = [cy["n_cells"] for cy in s["cycles"]]
    check(all(y > x for x, y in zip(cells, cells[1:])) and cells[-1] < 8 * 4 ** 3,
          "%s patch: the cells grow, not uniformly (%s)" % (shear, cells))


# ---- 2. effectivity on the Timoshenko strip
def strip(name, t, shear, cycles, refinement):
    q = 0.02 * (t / 0.01) ** 3  # the same deflections at every thickness
    exact, l = timoshenko_strip(t, q)
    cells = 16 if shear == "MITC4" else 8
    s, _ = run(args, name, mindlin_prm(
        "set Length x = %r\n  set Length y = 0.625\n  set Subdivisions = %d, 1" % (L, cells),
        t, q, shear, cycles, refinement, "set Level = %r" % -(G0 + t / 2), exact,
        "0: clamped; 1: clamped; 2: symmetry; 3: symmetry"), pinned="rigid")
    check(all(cy["converged"] for cy in s["cycles"]), "%s: every cycle converged" % name)
    return s


def effectivities(name, s, upper=10.0):
    eff = [cy["effectivity"] for cy in s["cycles"]]
    for cy in s["cycles"]:
        print("  %s cycle %2d: %6d DoFs  |e|_a %.3e  eta %.3e  without contact terms %.3e  "
              "effectivity %.2f" % (name, cy["cycle"], cy["n_dofs"], cy["errors"]["energy"],
                                    cy["error_estimate"],
                                    cy["error_estimate_parts"]["without_contact_terms"],
                                    cy["effectivity"]))
    check(len(eff) >= 4 and min(eff) >= 0.3 and max(eff) <= upper and max(eff) <= 3 * min(eff),
          "%s: effectivity in [0.3, %g], spread %.2f <= 3 (%.2f .. %.2f)"
          % (name, upper, max(eff) / min(eff), min(eff), max(eff)))


for t in (1.0, 0.1, 0.01, 0.001):
    effectivities("MITC4 t/L=%g" % (t / L), strip("strip_mitc4_%g" % t, t, "MITC4", 10, "adaptive"))
for t in (1.0, 0.1, 0.01, 0.001):
    effectivities("MITC9 t/L=%g" % (t / L), strip("strip_mitc9_%g" % t, t, "MITC9", 10, "adaptive"),
                  upper=10.0 if t >= 0.01 else 20.0)

# ---- 3. MITC9: adaptive against uniform
uniform = strip("rate_uniform", 0.01, "MITC9", 5, "global")["cycles"]
adapted = strip("rate_adaptive", 0.01, "MITC9", 30, "adaptive")["cycles"]
energy = lambda cy: cy["errors"]["energy"]
r_uniform = fitted_rate(uniform[-3:], energy)
late = [cy for cy in adapted if cy["n_dofs"] >= 2000]
r_adaptive = fitted_rate(late, energy)
check(len(late) >= 4 and r_adaptive >= 0.9 and r_adaptive >= r_uniform + 0.15,
      "MITC9 strip: adaptive |e|_a ~ N^-%.2f over %d cycles from 2000 DoFs, uniform N^-%.2f "
      "(need >= 0.9 and >= uniform + 0.15)" % (r_adaptive, len(late), r_uniform))
finest = uniform[-1]
reached = [cy for cy in adapted if energy(cy) <= energy(finest)]
print("  MITC9 strip: the finest uniform error %.2e (%d DoFs) is reached adaptively with %s DoFs"
      % (energy(finest), finest["n_dofs"], reached[0]["n_dofs"] if reached else "no"))
# ---- 4. the paper's test: adaptive against uniform
adaptive_run, _ = run(args, "paper_adaptive", shipped_prm("paper_mindlin_adaptive.prm", []),
                      pinned="rigid")
uniform_run, _ = run(args, "paper_uniform", shipped_prm(
    "paper_mindlin_adaptive.prm", [("Refinement", "global"),
                                   ("Target relative error estimate", "0"),
                                   ("Number of cycles", "4")]), pinned="rigid")
a, u = adaptive_run["cycles"][-1], uniform_run["cycles"][-1]
difference = abs(a["contact_force"] - u["contact_force"]) / u["contact_force"]
check(a["error_estimate_relative"] <= 0.05 and difference <= a["error_estimate_relative"],
      "paper's test: the adaptive reaction %.6f (%d DoFs, eta/|U|_a %.3f) and the uniform %.6f "
      "(%d DoFs) differ by %.1e <= eta/|U|_a"
      % (a["contact_force"], a["n_dofs"], a["error_estimate_relative"], u["contact_force"],
         u["n_dofs"], difference))
finish()
