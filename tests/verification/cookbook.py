"""Every recipe of doc/cookbook.md, parameters/cookbook/NAME.prm, runs as
shipped (the program's defaults, its own output directory) and gives what
the page says, each against an independent value:
 - sphere: the centre rests on the apex, w(5,5) = -0.5 + t/2 (geometry),
   up to the penetration the obstacle compliance reports;
 - bump: the centre rests on the bump, w(5,5) = -0.6 + t/2;
 - patch: without the obstacle (Level = -100) the probes agree with
   Navier's double sine series for the simply supported plate under the
   patch (200 x 200 terms) to 1e-4; with it the plate touches the plane;
 - cantilever: the tip deflection of the Timoshenko beam with the plate's
   stiffness D, to 1e-6 (MITC4 is exact at the nodes in cylindrical
   bending, and the default 'Contact formulation = gsv' has no theta-term
   bias; the paper's form would soften D by c/D = 0.45 %, doc/mindlin.md);
 - thickness: the Mindlin, Kirchhoff and 3D models (three methods) agree
   at a/t = 100, reaction to 1 %, w(2.5,5) to 0.5 %;
 - friction: the Coulomb bound |Lambda_t| <= F |Lambda_n|, a tangential
   resultant that vanishes by symmetry, and the reaction of the same
   plate without friction to 1 %;
 - elastic_foundation: the free plate's foundation carries the whole
   applied load, 6.25, to 1e-8 (balance), and the corners lift off;
 - manufactured: the last rates are 2 (L2) and 1 (H1) to 0.05;
 - mesh_file (the Mindlin plate): the load on the plate is q times the
   area of the square less the 32-gon of the hole (the mesh's straight
   edges), to 1e-10; the solution has the mesh's symmetries x -> 10 - x and
   x <-> y to 1e-8; the free hole edge rests on the plane and the clamped
   edge does not move;
 - data_obstacle (the same mesh, two regions loaded by -0.003 and -0.001,
   the substrate's heights from a file): the load on the plate is the
   regions' mean -0.002 times the area above (the four blocks have equal
   areas), to 1e-10; w is symmetric under x -> 10 - x and y -> 10 - y but
   not under x <-> y (the regions differ); the hole edge at (3.5, 5), a
   vertex of the mesh and a point of the data grid, rests on the sampled
   height -0.1 + 0.02 cos(0.7 pi) cos(pi) + t/2 to 1e-5 (the edge touches
   the substrate at some of its vertices; measured 1.3e-6)."""
import math, os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, close, finish

args = parse_args()
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
folder = os.path.join(root, "parameters", "cookbook")
recipes = {f[:-4]: open(os.path.join(folder, f)).read()
           for f in sorted(os.listdir(folder)) if f.endswith(".prm")}
page = open(os.path.join(root, "doc", "cookbook.md")).read()
for name in recipes:
    check("parameters/cookbook/%s.prm" % name in page,
          "doc/cookbook.md has a section for %s.prm" % name)
E, nu, t = 2e5, 0.3, 0.01


def solve(name, text=None):
    s, _ = run(args, name, recipes[name] if text is None else text, pinned=False)
    check(all(c["converged"] for c in s["cycles"]), name + ": every cycle converged")
    return s["cycles"][-1]


def set_entry(text, entry, value):
    new, n = re.subn(r"(?m)^(\s*set %s\s*=).*$" % re.escape(entry),
                     lambda m: m.group(1) + " " + value, text)
    check(n == 1, "one entry '%s' to change" % entry)
    return new


for name, apex in (("sphere", -0.5), ("bump", -0.6)):
    c = solve(name)
    pen, w = c["compliance_penetration"], c["probes"][0]
    check(abs(w - (apex + t / 2)) <= pen + 1e-6,
          "%s: w(5,5) = %.7f on the obstacle %.3f + t/2 (penetration %.1e)"
          % (name, w, apex, pen))

# patch: Navier's solution of the simply supported plate under the patch
c = solve("patch_free", set_entry(recipes["patch"], "Level", "-100"))
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
c = solve("patch")
check(c["contact_force"] > 0, "patch: the plate touches the plane (reaction %.4g)"
      % c["contact_force"])

# cantilever: cylindrical bending of the thick strip
c = solve("cantilever")
L, tc, q, kappa_s = 10., 0.5, -0.01, 5. / 6.
Dc = E * tc ** 3 / (12 * (1 - nu * nu))
G = E / (2 * (1 + nu))
w_tip = q * L ** 4 / (8 * Dc) + q * L ** 2 / (2 * kappa_s * G * tc)
close(c["probes"][0], w_tip, 1e-6, "cantilever: tip deflection against the Timoshenko beam")

# thickness: three models on the same plate
res = {m: solve("thickness_" + m, set_entry(recipes["thickness"], "Model", m))
       for m in ("mindlin", "kirchhoff", "elasticity")}
for m in ("kirchhoff", "elasticity"):
    close(res[m]["contact_force"], res["mindlin"]["contact_force"], 1e-2,
          "thickness: reaction, %s against Mindlin" % m)
    close(res[m]["probes"][1], res["mindlin"]["probes"][1], 5e-3,
          "thickness: w(2.5,5), %s against Mindlin" % m)

# friction: the Coulomb bound, symmetry, and the frictionless plate
c = solve("friction")
ex = dict(c["extra"])
check(ex["max_friction_ratio"] <= 1 + 1e-9,
      "friction: |Lambda_t| / (F |Lambda_n|) <= 1 (%.12g)" % ex["max_friction_ratio"])
for k in ("tangential_resultant_x", "tangential_resultant_y"):
    check(abs(ex[k]) <= 1e-6 * ex["tangential_force"],
          "friction: %s = %.2e vanishes by symmetry" % (k, ex[k]))
f0 = solve("friction_off", set_entry(recipes["friction"], "Friction coefficient", "0"))
close(c["contact_force"], f0["contact_force"], 1e-2, "friction: reaction against the frictionless plate")

# elastic foundation: the free plate's reaction is the applied load
c = solve("elastic_foundation")
close(c["contact_force"], 2.5 * 2.5 * 1.0, 1e-8, "elastic_foundation: reaction = applied load")
check(c["max_deflection"] > 0, "elastic_foundation: the corners lift off (max w %.3g)"
      % c["max_deflection"])

# manufactured: convergence rates of the membrane
c = solve("manufactured")
check(abs(c["rates"]["L2"] - 2) <= 0.05 and abs(c["rates"]["H1"] - 1) <= 0.05,
      "manufactured: rates L2 %.3f, H1 %.3f" % (c["rates"]["L2"], c["rates"]["H1"]))

# mesh file: the plate's area, the mesh's symmetries and its boundary ids
mesh = os.path.join(root, "parameters", "meshes", "plate_with_hole.msh")
text = set_entry(recipes["mesh_file"], "Mesh file", mesh)
text = set_entry(text, "Probe points", "3.5, 5; 6.5, 5; 5, 3.5; 2, 3; 8, 3; 3, 2; 0, 5; 1.5, 9")
c = solve("mesh_file", text)
area = 100 - 16 * 1.5 ** 2 * math.sin(2 * math.pi / 32)
close(dict(c["extra"])["load_total"], -0.02 * area, 1e-10,
      "mesh_file: the load on the square less the 32-gon of the hole")
w = c["probes"]
check(max(abs(w[0] - w[1]), abs(w[0] - w[2]), abs(w[3] - w[4]), abs(w[3] - w[5])) < 1e-8,
      "mesh_file: w is symmetric (%s)" % ", ".join("%.10f" % x for x in w[:6]))
pen = c["compliance_penetration"]
check(abs(w[0] - (-0.09 + t / 2)) <= pen + 1e-6 and c["contact_force"] > 0,
      "mesh_file: the free hole edge rests on the plane z = -0.09 + t/2 (w = %.7f, "
      "penetration %.1e)" % (w[0], pen))
check(w[6] == 0 and w[7] < -0.01,
      "mesh_file: the clamped edge (id 1) stays at 0, the plate inside sags (%.4f)" % w[7])

# data obstacle and region loads on the same mesh
text = set_entry(recipes["data_obstacle"], "Mesh file", mesh)
text = set_entry(text, "Data file", os.path.join(folder, "substrate.txt"))
c = solve("data_obstacle", text)
close(dict(c["extra"])["load_total"], -0.002 * area, 1e-10,
      "data_obstacle: the load on the plate is the regions' mean load times its area")
w = c["probes"]
check(abs(w[0] - w[1]) < 1e-8 and abs(w[2] - w[3]) < 1e-8 and abs(w[0] - w[2]) > 1e-3,
      "data_obstacle: w(5,2) = w(5,8) = %.7f, w(2,5) = w(8,5) = %.7f (the regions differ)"
      % (w[0], w[2]))
height = -0.1 + 0.02 * math.cos(0.7 * math.pi) * math.cos(math.pi)
pen = c["compliance_penetration"]
check(abs(w[4] - (height + t / 2)) <= pen + 1e-5 and c["contact_force"] > 0,
      "data_obstacle: the hole edge rests on the data, w(3.5,5) = %.7f = %.7f + t/2 "
      "(penetration %.1e)" % (w[4], height, pen))
finish()
