"""The Mindlin plate on meshes that are not uniform grids: curved, distorted
and skew cells, where the element data are computed per cell with the
covariant tying of the MITC shear strains (E = 2e5, nu = 0.3, kappa = 5/6;
no contact unless said).

- Circular plate of radius a = 5 under a uniform load q, closed forms
  (Timoshenko and Woinowsky-Krieger; the Mindlin part from the Marcus
  moment, Wang, Reddy and Lee, Shear deformable beams and plates, 2000):
    clamped:            w = q (a^2 - r^2)^2 / (64 D) + q (a^2 - r^2) / (4 kappa G t)
    simply supported:   w = q (a^2 - r^2) ((5 + nu)/(1 + nu) a^2 - r^2) / (64 D)
                            + q (a^2 - r^2) / (4 kappa G t)
  with phi = -grad of the first (Kirchhoff) part. MITC4 (t = 0.1 and
  t = 0.001, no locking) converges at the rates 2 (L2) and 1 (H1) of w and
  phi, MITC9 (on cells that follow the circle) at 3 and 2; the centre
  deflection to 1e-3 (MITC4, 3072 cells) and 1e-5 (MITC9).
- A smoothly distorted mesh of the unit square, hard simple support, the
  load -sin(pi x) sin(pi y) and its closed-form solution (as in
  mindlin_plate_bending), t = 0.001: MITC4 at the rates 2 and 1 on
  distorted cells.
- Morley's 30 degree skew plate (rhombus of side L, simply supported,
  uniform load, thin): centre deflection 0.408e-3 q L^4 / D (Morley, Skew
  plates and structures, 1963). The obtuse corners make the deflection
  converge slowly (about h^0.5); the Aitken extrapolation of the last
  three cycles (8^2 to 64^2 cells) lies within 3 % of it.
- The L-shape as the built-in shape (one element data for all cells) and
  as a Gmsh file of the same cells (element data per cell), with every
  boundary condition and a plane obstacle: the same discrete solution to
  round-off; MITC4 also from an Abaqus file of these cells.
- Adaptive cycles ('Refinement = adaptive', hanging nodes on curved and
  straight edges): the clamped disk (MITC4 and MITC9, t = 0.1) against its
  closed form, the effectivity eta / |e|_a in [0.3, 10] within a factor 3
  and the error falling; the L-shape built-in and from its Gmsh file, the
  same discrete solution to round-off on every adapted mesh."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, close, finish, write_msh

args = parse_args()
nu, E, kappa = 0.3, 2e5, 5 / 6
G = E / (2 * (1 + nu))

TEMPLATE = """set Model = mindlin
subsection Geometry
  %(geometry)s
  set Thickness = %(t)r
  set Number of cycles = %(cycles)d
  set Boundary conditions = %(bc)s
end
subsection Material
  set Young's modulus = %(E)r
end
subsection Load
  set Transverse load = %(load)s
end
subsection Obstacle
  set Level = %(level)r
end
subsection Contact
  set Nitsche theta = %(theta)d
end
subsection Mindlin
  set Shear treatment = %(shear)s
end
subsection Reference solution
  set Exact solution = %(exact)s
  set Function constants = %(constants)s
end
subsection Output
  set Probe points = %(probes)s
end
"""


def mindlin(name, **kw):
    entries = dict(E=E, level=-1e10, theta=0, exact="", constants="", probes="5, 5",
                   bc="all: clamped", shear="MITC4", cycles=4)
    entries.update(kw)
    s, _ = run(args, name, TEMPLATE % entries)
    return s["cycles"]


def check_rates(what, cycle, expected, tolerance):
    for norm, rate in expected.items():
        got = cycle["rates"][norm]
        check(abs(got - rate) < tolerance, "%s: rate of %s = %.3f (expected %d)"
              % (what, norm, got, rate))


# 1. circular plates
R2 = "(25-(x-5)^2-(y-5)^2)"
for bc, shear, t, cycles, rates, tolerance in (
        ("clamped", "MITC4", 0.1, 4, (2, 1), 1e-3),
        ("clamped", "MITC4", 0.001, 4, (2, 1), 1e-3),
        ("simply supported", "MITC4", 0.1, 4, (2, 1), 1e-3),
        ("clamped", "MITC9", 0.1, 3, (3, 2), 1e-5)):
    D = E * t ** 3 / (12 * (1 - nu * nu))
    q = -0.02 * (t / 0.1) ** 3
    if bc == "clamped":
        kirchhoff, slope, centre = R2 + "^2/(64*D)", R2 + "/(16*D)", 1.0
    else:
        c = (5 + nu) / (1 + nu)
        kirchhoff = R2 + "*(%r*25-(x-5)^2-(y-5)^2)/(64*D)" % c
        slope = "2*(%r*25+25-2*((x-5)^2+(y-5)^2))/(64*D)" % c
        centre = c
    exact = "q*(%s + %s/(4*k*G*th)); q*%s*(x-5); q*%s*(y-5)" % (kirchhoff, R2, slope, slope)
    what = "disk, %s, %s, t = %g" % (bc, shear, t)
    cycles_ = mindlin("disk_%s_%s_%g" % (bc.replace(" ", "_"), shear, t),
                      geometry="set Shape = disk\n  set Initial refinement = 1",
                      t=t, cycles=cycles, bc="all: " + bc, shear=shear,
                      load=repr(q), exact=exact,
                      constants="q=%r, D=%r, k=%r, G=%r, th=%r" % (q, D, kappa, G, t))
    last = cycles_[-1]
    check_rates(what, last, {"L2(w)": rates[0], "L2(phi)": rates[0],
                             "H1(w)": rates[1], "H1(phi)": rates[1]},
                0.15 if shear == "MITC9" else 0.1)
    w0 = q * 625 / (64 * D) * centre + q * 25 / (4 * kappa * G * t)
    close(last["probes"][0], w0, tolerance, what + ": centre deflection")
    if bc == "clamped" and t == 0.1:
        adapted = mindlin("disk_adaptive_%s" % shear,
                          geometry="set Shape = disk\n  set Initial refinement = 2\n"
                                   "  set Refinement = adaptive",
                          t=t, cycles=7 if shear == "MITC4" else 9, bc="all: " + bc,
                          shear=shear, load=repr(q), exact=exact,
                          constants="q=%r, D=%r, k=%r, G=%r, th=%r" % (q, D, kappa, G, t))
        eff = [c["effectivity"] for c in adapted]
        errors = [c["errors"]["energy"] for c in adapted]
        check(min(eff) >= 0.3 and max(eff) <= 10 and max(eff) <= 3 * min(eff)
              and errors[-1] < 0.5 * errors[0],
              "disk, clamped, %s, adaptive: effectivity %.2f .. %.2f, |e|_a %.2e -> %.2e "
              "(%d -> %d cells)" % (shear, min(eff), max(eff), errors[0], errors[-1],
                                    adapted[0]["n_cells"], adapted[-1]["n_cells"]))

# 2. distorted cells: the square's exact solution on a distorted mesh
t = 0.001
D = E * t ** 3 / (12 * (1 - nu * nu))
mesh = os.path.join(args.workdir, "distorted.msh")
write_msh(mesh, 1.0, 1.0, 4, 4, lambda x, y: False,
          lambda x, y: (x + 0.1 * math.sin(2 * math.pi * x) * math.sin(math.pi * y),
                        y + 0.1 * math.sin(math.pi * x) * math.sin(2 * math.pi * y)))
A = 1 / (4 * math.pi ** 4 * D) + 1 / (2 * math.pi ** 2 * kappa * G * t)
B = 1 / (4 * math.pi ** 3 * D)
last = mindlin("distorted", geometry="set Shape = mesh file\n  set Mesh file = " + mesh,
               t=t, cycles=5, bc="all: simply supported", load="-sin(pi*x)*sin(pi*y)",
               exact="-A*sin(pi*x)*sin(pi*y); B*cos(pi*x)*sin(pi*y); B*sin(pi*x)*cos(pi*y)",
               constants="A=%r, B=%r" % (A, B), probes="0.5, 0.5")[-1]
check_rates("distorted mesh, MITC4, t = 0.001", last,
            {"L2(w)": 2, "L2(phi)": 2, "H1(w)": 1, "H1(phi)": 1}, 0.1)
close(-last["probes"][0], A, 1e-3, "distorted mesh, MITC4, t = 0.001: centre deflection")

# 3. Morley's skew plate, L = 1, D = 1, q = -1
c30, s30 = math.cos(math.pi / 6), math.sin(math.pi / 6)
mesh = os.path.join(args.workdir, "skew.msh")
write_msh(mesh, 1.0, 1.0, 8, 8, lambda x, y: False, lambda x, y: (x + y * c30, y * s30))
t = 0.001
cycles_ = mindlin("morley", geometry="set Shape = mesh file\n  set Mesh file = " + mesh,
                  t=t, E=12 * (1 - nu * nu) / t ** 3, cycles=4, bc="all: simply supported",
                  load="-1", probes="%r, %r" % ((1 + c30) / 2, s30 / 2))
w = [-c["probes"][0] for c in cycles_[-3:]]
aitken = w[2] + (w[2] - w[1]) ** 2 / ((w[1] - w[0]) - (w[2] - w[1]))
check(all(a < b for a, b in zip(w, w[1:])), "Morley: the centre deflection grows under "
      "refinement (%s)" % ", ".join("%.5e" % v for v in w))
close(aitken, 0.408e-3, 3e-2, "Morley: the extrapolated centre deflection")

# 4. the L-shape, built-in and from a file of the same cells
BC = "0: clamped; 1: simply supported; 2: clamped; 3: symmetry; 4: free"
mesh = os.path.join(args.workdir, "l_shape.msh")
write_msh(mesh, 2.0, 1.0, 8, 4, lambda x, y: x > 1 and y > 0.5)
common = "set Length x = 2\n  set Length y = 1\n  set Subdivisions = 8, 4\n  "
runs = {}
for shear, refinement in (("MITC4", ""), ("MITC9", ""), ("MITC4", "adaptive"),
                          ("MITC9", "adaptive")):
    for name, geometry in (("built-in", "set Shape = L-shape"),
                           ("file", "set Shape = mesh file\n  set Mesh file = " + mesh)):
        if refinement:
            geometry += "\n  set Refinement = adaptive"
        runs[shear + refinement, name] = mindlin(
            "l_shape_%s_%s%s" % (shear, name.replace("-", "_"), refinement),
            geometry=common + geometry, t=0.01, cycles=5 if refinement else 3,
            bc=BC, shear=shear, load="-0.02", level=-0.02, theta=1,
            probes="0.3, 0.5; 0.5, 0.25; 1.7, 0.2")
    for a, b in zip(runs[shear + refinement, "built-in"], runs[shear + refinement, "file"]):
        what = "L-shape, %s%s, cycle %d" % (shear, ", adaptive" if refinement else "",
                                            a["cycle"])
        check(a["n_dofs"] == b["n_dofs"], "%s: %d DoFs, from the file %d"
              % (what, a["n_dofs"], b["n_dofs"]))
        scale = max(abs(p) for p in a["probes"])
        diff = max(abs(p - q) for p, q in zip(a["probes"], b["probes"]))
        check(a["contact_force"] > 0 and
              abs(a["contact_force"] - b["contact_force"]) < 1e-8 * a["contact_force"]
              and diff < 1e-9 * scale,
              "%s: reaction %.10f and probes agree with the mesh file (%.1e, %.1e)"
              % (what, a["contact_force"], abs(a["contact_force"] - b["contact_force"]), diff))

# the same cells as an Abaqus file (boundary ids from its surfaces SS<id>)
inp = os.path.join(args.workdir, "l_shape.inp")
write_msh(inp, 2.0, 1.0, 8, 4, lambda x, y: x > 1 and y > 0.5)
abaqus = mindlin("l_shape_MITC4_abaqus",
                 geometry=common + "set Shape = mesh file\n  set Mesh file = " + inp,
                 t=0.01, cycles=3, bc=BC, shear="MITC4", load="-0.02", level=-0.02,
                 theta=1, probes="0.3, 0.5; 0.5, 0.25; 1.7, 0.2")
a, b = runs["MITC4", "built-in"][-1], abaqus[-1]
close(b["contact_force"], a["contact_force"], 1e-8, "L-shape, MITC4: reaction, Abaqus file vs built-in")
for j in range(3):
    close(b["probes"][j], a["probes"][j], 1e-9,
          "L-shape, MITC4: probe %d, Abaqus file vs built-in" % j)

finish()
