"""Every recipe of doc/cookbook.md runs as written (the program's defaults,
its own output directory) and gives what the page says, each against an
independent value:
 1. sphere: the centre rests on the apex, w(5,5) = -0.5 + t/2 (geometry),
    up to the penetration the obstacle compliance reports;
 2. formula obstacle: the centre rests on the bump, w(5,5) = -0.6 + t/2;
 3. patch load: run again without the obstacle (Level = -100), the probes
    agree with Navier's double sine series for the simply supported plate
    under the patch (200 x 200 terms) to 1e-4 relative;
 4. cantilever strip: the tip deflection of the Timoshenko beam with the
    plate's stiffness softened by the theta-terms' c/D (doc/mindlin.md),
    to 1e-6 relative (MITC4 is exact at the nodes in cylindrical bending);
 5. manufactured membrane: the last rates are 2 (L2) and 1 (H1) to 0.05."""
import math, os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, close, finish

args = parse_args()
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
page = open(os.path.join(root, "doc", "cookbook.md")).read()
recipes = re.findall(r"```prm\n(.*?)```", page, re.S)
check(len(recipes) == 5, "doc/cookbook.md has 5 recipes (found %d)" % len(recipes))
E, nu, t = 2e5, 0.3, 0.01


def last(summary):
    c = summary["cycles"][-1]
    check(all(x["converged"] for x in summary["cycles"]), "every cycle converged")
    return c


def rests_on(name, text, apex):
    c = last(run(args, name, text, pinned=False)[0])
    pen = c["compliance_penetration"]
    w = c["probes"][0]
    check(abs(w - (apex + t / 2)) <= pen + 1e-6,
          "%s: w(5,5) = %.7f on the obstacle %.3f + t/2 (penetration %.1e)"
          % (name, w, apex, pen))


rests_on("sphere", recipes[0], -0.5)
rests_on("bump", recipes[1], -0.6)

# 3. Navier's solution of the simply supported plate under the patch
text = recipes[2].replace("set Level = -10\n", "set Level = -100\n")
check(text != recipes[2], "patch: the obstacle moved away")
c = last(run(args, "patch_free", text, pinned=False)[0])
a = b = 10.
x1, x2, y1, y2, q0 = 2.5, 5., 5., 7.5, -0.05
D = E * t ** 3 / (12 * (1 - nu * nu))


def navier(x, y, n_terms=200):
    s = 0.
    for m in range(1, n_terms + 1):
        fm = (math.cos(m * math.pi * x1 / a) - math.cos(m * math.pi * x2 / a)) / m
        sm = math.sin(m * math.pi * x / a)
        for n in range(1, n_terms + 1):
            fn = (math.cos(n * math.pi * y1 / b) - math.cos(n * math.pi * y2 / b)) / n
            qmn = 4 * q0 / (math.pi ** 2) * fm * fn
            s += qmn / (D * math.pi ** 4 * (m * m / a ** 2 + n * n / b ** 2) ** 2) * \
                sm * math.sin(n * math.pi * y / b)
    return s


for i, p in enumerate([(5., 5.), (4., 5.5)]):
    close(c["probes"][i], navier(*p), 1e-4, "patch: w%s against Navier's series" % (p,))
c = last(run(args, "patch", recipes[2], pinned=False)[0])
check(c["contact_force"] > 0, "patch: the plate touches the plane (reaction %.4g)"
      % c["contact_force"])

# 4. cylindrical bending of the thick cantilever strip
c = last(run(args, "cantilever", recipes[3], pinned=False)[0])
L, tc, q, gamma0, kappa_s = 10., 0.5, -0.01, 200., 5. / 6.
Dc = E * tc ** 3 / (12 * (1 - nu * nu))
lam_E = nu / ((1 + nu) * (1 - 2 * nu))
c_D = 3 * (1 - nu * nu) * lam_E ** 2 / gamma0
G = E / (2 * (1 + nu))
w_tip = q * L ** 4 / (8 * Dc * (1 - c_D)) + q * L ** 2 / (2 * kappa_s * G * tc)
close(c["probes"][0], w_tip, 1e-6, "cantilever: tip deflection against the Timoshenko beam")

# 5. convergence rates of the manufactured membrane
c = last(run(args, "manufactured", recipes[4], pinned=False)[0])
check(abs(c["rates"]["L2"] - 2) <= 0.05 and abs(c["rates"]["H1"] - 1) <= 0.05,
      "manufactured: rates L2 %.3f, H1 %.3f" % (c["rates"]["L2"], c["rates"]["H1"]))
finish()
