"""The membrane on the built-in shapes and on a mesh file, against closed
forms (T = 1, q = -1, so -Laplace(w) = -1, and w = r^2/4 + A ln r + B in
an axisymmetric free region):

- the clamped unit disk: w = (r^2 - 1)/4; the L2 and H1 errors fall at the
  rates 2 and 1 of Q1 (the curved edge by its manifold and a Q1 mapping);
- the clamped unit disk on the plane w >= -0.1: the membrane rests on the
  disk r <= b, where w(b) = -0.1 and w'(b) = 0 give b^2/4 - (b^2/2) ln b
  - 1/4 = -0.1; the reaction is |q| pi b^2 (no line force at r = b);
- the annulus 0.5 < r < 1, clamped outside (id 0) and free inside (id 1):
  w(1) = 0 and w'(0.5) = 0 give A = -1/8, B = -1/4;
- the L-shape and the rectangle with hole on a plane obstacle, built in and
  read from a Gmsh file (the L-shape) or a UCD file (the rectangle with
  hole) of the same cells and boundary ids: the same solution to
  round-off.

Each shape also runs with 'Refinement = adaptive' (curved edges keep their
manifolds, mesh files refine like the built-in shapes): on the disk on the
plane and on the annulus the effectivity eta / |e|_a against the closed
form stays in [0.3, 10] within a factor 3, and the adaptive L-shape and
rectangle with hole agree with their mesh files to round-off."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, finish, write_msh

args = parse_args()

BASE = """set Model = membrane
subsection Geometry
  %(geometry)s
  set Initial refinement = %(refinement)d
  set Number of cycles = %(cycles)d
end
subsection Load
  set Transverse load = -1
end
subsection Obstacle
  set Type = plane
  set Level = %(level)r
end
subsection Membrane
  set Tension = 1
end
subsection Nonlinear solver
  set Tolerance = 1e-10
  set Maximum iterations = 100
end
subsection Reference solution
  set Exact solution = %(exact)s
end
subsection Output
  set Probe points = %(probes)s
end
"""
ADAPTIVE = "\n  set Refinement = adaptive"


def membrane(name, geometry, level=-1e6, refinement=1, cycles=4, exact="", probes="0, 0"):
    s, _ = run(args, name, BASE % dict(geometry=geometry, level=level, refinement=refinement,
                                       cycles=cycles, exact=exact, probes=probes))
    for c in s["cycles"]:
        check(c["converged"], "%s cycle %d: converged" % (name, c["cycle"]))
    return s["cycles"]


def effectivity_band(name, cycles):
    eff = [c["effectivity"] for c in cycles]
    check(min(eff) >= 0.3 and max(eff) <= 10 and max(eff) <= 3 * min(eff),
          "%s: effectivity in [0.3, 10] within a factor 3 (%s)" % (name, ", ".join("%.2f" % e for e in eff)))


def rates(cycles, norm):
    e = [c["errors"][norm] for c in cycles]
    return e, [math.log2(a / b) for a, b in zip(e, e[1:])]


DISK = "set Shape = disk\n  set Center = 0, 0\n  set Radius = 1\n  set Boundary conditions = all: clamped"

# 1. the clamped disk without obstacle
cycles = membrane("disk", DISK, exact="(x^2 + y^2 - 1)/4", probes="0, 0; 0.5, 0")
for norm, expected in (("L2", 2.0), ("H1", 1.0)):
    e, r = rates(cycles, norm)
    check(r[-1] >= expected - 0.1,
          "disk: %s error %s falls at the rate %.2f >= %.1f"
          % (norm, ", ".join("%.2e" % x for x in e), r[-1], expected - 0.1))
w0 = cycles[-1]["probes"][0]
check(abs(w0 + 0.25) < 2e-4, "disk: w(0) = %.6f vs -1/4" % w0)

# 2. the clamped disk on the plane w >= -0.1
d = 0.1
lo, hi = 0.3, 0.9
for _ in range(60):
    b = 0.5 * (lo + hi)
    if b * b / 4 - b * b / 2 * math.log(b) - 0.25 + d < 0:
        lo = b
    else:
        hi = b
reaction = math.pi * b * b
w_free = lambda r: -d if r <= b else r * r / 4 - b * b / 2 * math.log(r) - 0.25
xs = (0.25, 0.7, 0.85)
cycles = membrane("disk_obstacle", DISK, level=-d, cycles=5,
                  probes="; ".join("%g, 0" % x for x in xs))
errors = []
for c in cycles:
    errors.append(abs(c["contact_force"] - reaction) / reaction)
check(errors[-1] < 2e-3 and errors[-1] < errors[0] / 4,
      "disk on a plane: reaction %.6f vs pi b^2 = %.6f (b = %.6f), relative errors %s"
      % (cycles[-1]["contact_force"], reaction, b, ", ".join("%.1e" % x for x in errors)))
for x, w in zip(xs, cycles[-1]["probes"]):
    check(abs(w - w_free(x)) < 2e-4, "disk on a plane: w(%g) = %.6f vs %.6f" % (x, w, w_free(x)))
uniform_cycles = cycles
r = "sqrt(x^2 + y^2)"
exact = "(%s < %r) ? %r : %s^2/4 - %r*log(%s) - 0.25" % (r, b, -d, r, b * b / 2, r)
cycles = membrane("disk_obstacle_adaptive", DISK + ADAPTIVE, level=-d, cycles=14, exact=exact,
                  probes="; ".join("%g, 0" % x for x in xs))
effectivity_band("disk on a plane, adaptive", cycles)
# (Q1 on this smooth-but-for-the-free-boundary problem: adaptive meshes are
# as good as uniform ones, not better)
err = abs(cycles[-1]["contact_force"] - reaction) / reaction
uniform = [e for c, e in zip(uniform_cycles, errors) if c["n_dofs"] <= cycles[-1]["n_dofs"]][-1]
check(err <= uniform, "disk on a plane, adaptive: reaction %.6f vs %.6f (rel. %.1e at %d DoFs, "
      "uniform %.1e at fewer DoFs)" % (cycles[-1]["contact_force"], reaction, err, cycles[-1]["n_dofs"], uniform))

# 3. the annulus, clamped outside, free inside
A, B = -1.0 / 8, -0.25
cycles = membrane("annulus",
                  "set Shape = annulus\n  set Center = 0, 0\n  set Radius = 1\n"
                  "  set Inner radius = 0.5\n  set Boundary conditions = 0: clamped; 1: free",
                  exact="(x^2 + y^2)/4 - log(x^2 + y^2)/16 - 1/4", probes="0.5, 0; 0, 0.75")
for norm, expected in (("L2", 2.0), ("H1", 1.0)):
    e, r = rates(cycles, norm)
    check(r[-1] >= expected - 0.1,
          "annulus: %s error %s falls at the rate %.2f >= %.1f"
          % (norm, ", ".join("%.2e" % x for x in e), r[-1], expected - 0.1))
for (x, y), w in zip(((0.5, 0), (0, 0.75)), cycles[-1]["probes"]):
    r = math.hypot(x, y)
    exact = r * r / 4 + A * math.log(r) + B
    check(abs(w - exact) < 2e-4, "annulus: w(%g, %g) = %.6f vs %.6f" % (x, y, w, exact))
cycles = membrane("annulus_adaptive",
                  "set Shape = annulus\n  set Center = 0, 0\n  set Radius = 1\n"
                  "  set Inner radius = 0.5\n  set Boundary conditions = 0: clamped; 1: free" + ADAPTIVE,
                  exact="(x^2 + y^2)/4 - log(x^2 + y^2)/16 - 1/4", probes="0.5, 0; 0, 0.75", cycles=6)
effectivity_band("annulus, adaptive", cycles)


# 4. built-in straight-edged shapes against the same cells from a Gmsh file
BC = "set Boundary conditions = 0: clamped; 1: simply supported; 2: clamped; 3: free; 4: clamped"
SHAPES = {
    "L-shape": ("set Shape = L-shape", lambda x, y: x > 1 and y > 0.5, -0.05),
    "rectangle with hole": ("set Shape = rectangle with hole\n  set Hole size = 1, 0.5",
                            lambda x, y: abs(x - 1) < 0.5 and abs(y - 0.5) < 0.25, -0.01),
}
for (shape, (entry, removed, level)), ext in zip(SHAPES.items(), ("msh", "ucd")):
    tag = shape.replace(" ", "_")
    mesh = os.path.join(args.workdir, tag + "." + ext)
    write_msh(mesh, 2.0, 1.0, 8, 4, removed)
    geometry = "set Length x = 2\n  set Length y = 1\n  set Subdivisions = 8, 4\n  " + BC
    probes = "0.3, 0.5; 0.5, 0.25; 1.7, 0.2"
    for refinement, cycles in (("", 3), (ADAPTIVE, 5)):
        built = membrane(tag, geometry + "\n  " + entry + refinement, level=level, cycles=cycles,
                         probes=probes)
        read = membrane(tag + "_file", geometry + "\n  set Shape = mesh file\n  set Mesh file = " +
                        mesh + refinement, level=level, cycles=cycles, probes=probes)
        label = shape + " (%s file%s)" % (ext, ", adaptive" if refinement else "")
        for a, b in zip(built, read):
            check(a["n_dofs"] == b["n_dofs"] and a["nonlinear_iterations"] == b["nonlinear_iterations"],
                  "%s cycle %d: %d DoFs and %d iterations, from the file %d and %d"
                  % (label, a["cycle"], a["n_dofs"], a["nonlinear_iterations"], b["n_dofs"],
                     b["nonlinear_iterations"]))
            diff = max([abs(a["contact_force"] - b["contact_force"])] +
                       [abs(p - q) for p, q in zip(a["probes"], b["probes"])])
            check(diff < 1e-12 and a["contact_force"] > 0,
                  "%s cycle %d: reaction %.12f and probes agree with the mesh file to %.1e"
                  % (label, a["cycle"], a["contact_force"], diff))

finish()
