"""The membrane strip on a flat obstacle, a one-dimensional contact problem
in closed form: [0, L] x [0, W] with w = 0 at x = 0 and x = L, free edges
y = 0, W, tension T, uniform load q < 0, obstacle psi = -d. The membrane
rests on the obstacle on [a, L - a], a = sqrt(2 T d / |q|); outside, w =
-d + |q| (x - a)^2 / (2 T) (w and w' are continuous at x = a). The contact
pressure is |q| on the contact zone, the total reaction |q| (L - 2a) W.
Checks the contact zone (from the contact area), the reaction and the
deflections on five nested meshes for Q1 and Q2 (Newton, theta = 1), and
on four meshes for the fixed point scheme and theta = 0, -1 (Q2): each
converges to the closed form. Then the same on an elastic obstacle (below)."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, finish, first_corrections
from membrane_lib.membrane import membrane_prm

args = parse_args()
L, W, T, q, a = 1.0, 0.25, 1.5, -1.0, 0.3
d = a * a * abs(q) / (2 * T)
reaction = abs(q) * (L - 2 * a) * W


def w_exact(x):
    x = min(x, L - x)
    return -d if x >= a else -d + abs(q) * (x - a) ** 2 / (2 * T)


xs = [0.1, 0.2, 0.5]
probes = "; ".join("%g, %g" % (x, W / 2) for x in xs)


def strip(name, cycles, **kw):
    s, log = run(args, name,
                 membrane_prm(lx=L, ly=W, sub=(8, 2), cycles=cycles, load=q, tension=T,
                              edges="0: clamped; 1: clamped; 2: free; 3: free", probes=probes,
                              obstacle="set Type = plane\n  set Level = %r" % -d, **kw))
    deflection_errors = []
    for c in s["cycles"]:
        n = 8 * 2 ** c["cycle"]
        what = "%s n=%d" % (name, n)
        check(c["converged"], "%s: converged" % what)
        zone = c["contact_area"] / W
        # the contact set is where the pressure is positive at the contact
        # points: exact up to the cell on either side of each free boundary
        check(abs(zone - (L - 2 * a)) <= 2.0 / n,
              "%s: contact zone %.5f vs exact %.5f (within a cell per side)" % (what, zone, L - 2 * a))
        err = abs(c["contact_force"] - reaction) / reaction
        check(err <= 0.2 / n, "%s: reaction %.8e vs exact %.8e (rel. %.1e <= 0.2/n)"
              % (what, c["contact_force"], reaction, err))
        deflection_errors.append(max(abs(w - w_exact(x)) for x, w in zip(xs, c["probes"])))
    e = deflection_errors
    rate = math.log2(e[0] / e[-1]) / (len(e) - 1)
    check(rate >= 1.5, "%s: deflection error at the probes falls at the mean rate %.2f >= 1.5 (%s)"
          % (name, rate, ", ".join("%.1e" % x for x in e)))
    last = s["cycles"][-1]
    check(abs(last["contact_force"] - reaction) <= 2e-4 * reaction,
          "%s: reaction on the finest mesh within 2e-4 (%.8e)" % (name, last["contact_force"]))
    # nested iteration: the first correction of a cycle is the change of
    # the discrete solution between meshes, not the solution itself
    firsts = first_corrections(log)[1:]
    check(max(firsts) < 0.2 and firsts[-1] < firsts[0],
          "%s: first corrections of the nested cycles %s below 0.2, the last below the first"
          % (name, ", ".join("%.1e" % f for f in firsts)))
    return s


for degree in (1, 2):
    strip("strip_q%d" % degree, 5, degree=degree)


# The same strip on an elastic obstacle of compliance kappa (a Winkler
# layer, p = (psi - w)/kappa where in contact). With l = sqrt(T kappa) and
# the contact zone |x - L/2| < b: w = psi - |q| kappa + A cosh((x - L/2)/l)
# there, A = |q| kappa / cosh(b/l) (p = 0 at its ends), and w = |q| x^2/(2T)
# + B x outside, B fixed by w = psi at x0 = L/2 - b; b makes w' continuous.
# The reaction is 2 |q| (b - l tanh(b/l)) W.
kappa = 0.05 ** 2 / T
ell = math.sqrt(T * kappa)


def slope_jump(b):
    x0 = L / 2 - b
    B = (-d - abs(q) * x0 ** 2 / (2 * T)) / x0
    return abs(q) * x0 / T + B + abs(q) * kappa / ell * math.tanh(b / ell)


lo, hi = 1e-9, L / 2 - 1e-9
for _ in range(200):
    mid = 0.5 * (lo + hi)
    if (slope_jump(lo) > 0) == (slope_jump(mid) > 0):
        lo = mid
    else:
        hi = mid
b = 0.5 * (lo + hi)
x0 = L / 2 - b
A, B = abs(q) * kappa / math.cosh(b / ell), (-d - abs(q) * x0 ** 2 / (2 * T)) / x0
compliant_reaction = 2 * abs(q) * (b - ell * math.tanh(b / ell)) * W


def w_compliant(x):
    x = min(x, L - x)
    if x >= x0:
        return -d - abs(q) * kappa + A * math.cosh((x - L / 2) / ell)
    return abs(q) * x * x / (2 * T) + B * x


for degree in (1, 2):
    name = "compliant_q%d" % degree
    s, _ = run(args, name,
               membrane_prm(lx=L, ly=W, sub=(8, 2), cycles=5, load=q, tension=T, degree=degree,
                            edges="0: clamped; 1: clamped; 2: free; 3: free", probes=probes,
                            obstacle="set Type = plane\n  set Level = %r" % -d,
                            extra="subsection Contact\n  set Obstacle compliance = %r\nend\n"
                            % kappa))
    errors = []
    for c in s["cycles"]:
        check(c["converged"], "%s n=%d: converged" % (name, 8 * 2 ** c["cycle"]))
        errors.append((abs(c["contact_force"] - compliant_reaction) / compliant_reaction,
                       max(abs(w - w_compliant(x)) for x, w in zip(xs, c["probes"]))))
    last = s["cycles"][-1]
    check(errors[-1][0] <= 1e-4 and errors[-1][1] <= 1e-5,
          "%s: reaction %.8e vs exact %.8e, deflection error %.1e at the probes (b = %.5f)"
          % (name, last["contact_force"], compliant_reaction, errors[-1][1], b))
    # (the third derivative of w jumps at the ends of the contact zone,
    # which bounds the rate of Q2, whose errors start two orders lower)
    rate = math.log2(errors[0][1] / errors[-1][1]) / (len(errors) - 1)
    least = 1.5 if degree == 1 else 1.0
    check(rate >= least, "%s: deflection error falls at the mean rate %.2f >= %g (%s)"
          % (name, rate, least, ", ".join("%.1e" % e[1] for e in errors)))
    # the membrane sinks into the layer by kappa p <= kappa |q|
    pen = last["extra"]["max_penetration"]
    check(abs(pen - abs(q) * kappa * (1 - 1 / math.cosh(b / ell))) <= 0.02 * abs(q) * kappa,
          "%s: largest penetration %.4e vs exact kappa p(L/2) = %.4e"
          % (name, pen, abs(q) * kappa * (1 - 1 / math.cosh(b / ell))))
# (Q2: with Q1, Delta_h w = 0 on these cells and theta has no term to act on)
for variant, kw in (("fixed_point", dict(scheme="fixed point")), ("theta0", dict(theta=0)),
                    ("theta-1", dict(theta=-1))):
    kw["degree"] = 2
    strip("strip_" + variant, 4, **kw)
finish()
