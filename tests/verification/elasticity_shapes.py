"""The 3D model on plates that are not made of the rectangle's grid: the
disk and the annulus (the plate's mesh extruded, a cylindrical manifold on
the circular side faces, the mapping of the element's degree) and mesh
files; one Q2 layer, refined in plane from cycle to cycle with the solution
carried over by evaluation on the previous mesh.

- Clamped thin disk (radius a = 5, t = 0.01, E = 2e5, nu = 0.3, the load
  q = -0.02 as a body force q/t, no obstacle): the deflection converges to
  the closed form w = q (a^2 - r^2)^2 / (64 D) + q (a^2 - r^2) / (4 kappa
  G t) (Timoshenko and Woinowsky-Krieger; the shear part, 2e-5 of w0, is
  the Mindlin correction, the 3D one is O((t/a)^2) = 4e-6) at the centre
  and at r = 2.5: within 1 % and 1.5 % on 768 cells in plane (measured
  0.72 % and 0.96 %), each of the last two refinements shrinks the errors
  by at least 2.5x (measured 6.0x, 3.0x and 6.7x, 3.1x), and the solution
  has the mesh's quarter-turn symmetry to 1e-6.
- The disk on a plane obstacle on 2 MPI ranks gives the 1-rank run to
  1e-5 (elasticity_mpi's tolerance): the extruded mesh with its manifold,
  the transfer between the cycles' meshes (whose exactness on nested
  meshes elasticity_patch checks) and the contact on a partition.
- With Q1 elements (the mapping stays quadratic on the circle) the disk
  runs its cycles too; the thin Q1 layer locks, so its centre deflection
  grows from cycle to cycle and stays below the closed form.
- The annulus (radii 2 and 5, outer edge clamped, inner edge free, the
  plane at -0.3 below the lower face) against the Mindlin MITC9 plate on
  the same annulus (a second method; its reaction changes by 0.07 % from
  its 6,528- to its 25,344-DoF mesh): as on the square (models_agree) the
  coarse 3D mesh is stiffer, its reaction lies below the plate's, within
  4 % on 768 cells in plane (measured -1.8 %), and the last refinement
  shrinks the difference by at least 2x (measured 2.8x).
- The L-shape as a Gmsh file of the cells of the built-in L-shape gives
  the built-in run's reaction and probes to 1e-9 (the same discrete
  problem; the meshes number their cells differently), each cycle started
  from the previous one."""
import math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, close, finish, write_msh

args = parse_args()
E, nu, q = 2e5, 0.3, -0.02
kappa, G = 5 / 6, E / (2 * (1 + nu))

SOLID = """set Model = elasticity
subsection Geometry
  %(shape)s
  set Thickness = %(t)r
  set Boundary conditions = %(bc)s
  set Subdivisions = %(sub)s
  set Number of cycles = %(cycles)d
end
subsection Material
  set Young's modulus = %(E)r
end
subsection Load
  set Transverse load = %(q)r
end
subsection Obstacle
  set Level = %(level)r
end
subsection Elasticity
  set Refine through thickness = false
end
subsection Output
  set Probe points = %(probes)s
end
"""
DISK = "set Shape = disk\n  set Center = 5, 5\n  set Radius = 5"


def solid(name, np=1, **kw):
    entries = dict(t=0.01, E=E, q=q, sub="1, 1, 1", bc="all: clamped", cycles=4)
    entries.update(kw)
    s, _ = run(args, name, SOLID % entries, np=np, pinned="rigid")
    check(all(c["converged"] for c in s["cycles"]), "%s: every cycle converged" % name)
    return s["cycles"]


# the clamped disk against the closed form
t, a = 0.01, 5.0
D = E * t ** 3 / (12 * (1 - nu ** 2))
exact = lambda r: q * (a * a - r * r) ** 2 / (64 * D) + q * (a * a - r * r) / (4 * kappa * G * t)
cycles = solid("disk_clamped", shape=DISK, level=-1e10, probes="5, 5; 7.5, 5; 5, 7.5; 2.5, 5")
e0 = [abs(c["probes"][0] / exact(0.) - 1) for c in cycles]
e1 = [abs(c["probes"][1] / exact(2.5) - 1) for c in cycles]
check(e0[3] < 1e-2 and e1[3] < 1.5e-2,
      "clamped disk, 768 cells: w(0) within 1 %% and w(2.5) within 1.5 %% of the closed "
      "form (%.3f %%, %.3f %%)" % (100 * e0[3], 100 * e1[3]))
for e, where in ((e0, "w(0)"), (e1, "w(2.5)")):
    check(e[1] >= 2.5 * e[2] and e[2] >= 2.5 * e[3],
          "clamped disk: the error of %s falls by at least 2.5x per refinement "
          "(%.3g, %.3g, %.3g)" % (where, e[1], e[2], e[3]))
w = cycles[3]["probes"]
# (to the accuracy of locating a probe in the curved cells)
check(abs(w[1] - w[2]) < 1e-6 * abs(w[1]) and abs(w[1] - w[3]) < 1e-6 * abs(w[1]),
      "clamped disk: w(7.5,5) = w(5,7.5) = w(2.5,5) (%.12f, %.12f, %.12f)" % (w[1], w[2], w[3]))

# Q1 elements on the disk: the mapping stays quadratic on the circle, so
# the cycles' points are found; the thin Q1 layer locks, so the centre
# deflection grows from cycle to cycle towards the closed form from below
s, _ = run(args, "disk_clamped_Q1", SOLID % dict(t=0.01, E=E, q=q, sub="1, 1, 1",
                                                 bc="all: clamped", cycles=3, shape=DISK,
                                                 level=-1e10, probes="5, 5")
           + "subsection Elasticity\n  set Polynomial degree = 1\nend\n", pinned="rigid")
w = [c["probes"][0] for c in s["cycles"]]
check(all(c["converged"] for c in s["cycles"]) and 0 > w[0] > w[1] > w[2] > exact(0.),
      "Q1 disk: every cycle converged, w(0) = %s falls towards %.4f" %
      (", ".join("%.5f" % v for v in w), exact(0.)))

# the disk on a plane obstacle, on 1 and 2 ranks
probes = "5, 5; 7.5, 5; 5, 8"
runs = {np: solid("disk_contact_np%d" % np, np=np, shape=DISK, level=-0.3, probes=probes,
                  cycles=3)
        for np in (1, 2)}
a1, a2 = runs[1][-1], runs[2][-1]
check(a1["contact_force"] > 0, "disk on the plane: in contact (reaction %.6f)"
      % a1["contact_force"])
close(a2["contact_force"], a1["contact_force"], 1e-5, "disk on the plane: reaction, 2 ranks vs 1")
for j in range(3):
    close(a2["probes"][j], a1["probes"][j], 1e-5, "disk on the plane: probe %d, 2 ranks vs 1" % j)

# the annulus on a plane obstacle: 3D against the Mindlin MITC9 plate
ANNULUS = ("set Shape = annulus\n  set Center = 5, 5\n  set Radius = 5\n"
           "  set Inner radius = 2")
BC = "0: clamped; 1: free"
ring = solid("annulus_3d", shape=ANNULUS, bc=BC, level=-0.3, probes="5, 2.5")
plate, _ = run(args, "annulus_mitc9",
               "set Model = mindlin\nsubsection Geometry\n  %s\n  set Boundary conditions = %s\n"
               "  set Number of cycles = 5\nend\nsubsection Obstacle\n  set Level = -0.3\nend\n"
               "subsection Mindlin\n  set Shear treatment = MITC9\nend\n" % (ANNULUS, BC),
               pinned="rigid")
check(all(c["converged"] for c in plate["cycles"]), "annulus MITC9: every cycle converged")
reference = plate["cycles"][-1]["contact_force"]
diff = [c["contact_force"] / reference - 1 for c in ring]
check(-0.04 <= diff[3] <= 0.,
      "annulus 3D, 768 cells: reaction %.3f %% of the MITC9 plate's, in [-4 %%, 0]"
      % (100 * diff[3]))
check(abs(diff[2]) >= 2. * abs(diff[3]),
      "annulus: the last refinement shrinks the difference to MITC9 by at least 2x "
      "(%.2f %% -> %.2f %%)" % (100 * diff[2], 100 * diff[3]))

# the L-shape: built-in and as a Gmsh file of the same cells
mesh = os.path.join(args.workdir, "l_shape.msh")
write_msh(mesh, 10.0, 10.0, 4, 4, lambda x, y: x > 5 and y > 5, lambda x, y: (x, y))
probes = "2.5, 2.5; 1, 5; 5, 1"
# (both from the previous cycle: the plate predictor's plate evaluates the
# built-in grid and the file's cells differently, to round-off)
no_predictor = "subsection Elasticity\n  set Plate predictor = false\nend\n"
L = {name: solid("L_" + name, shape=shape + "\nend\n" + no_predictor + "subsection Geometry",
                 sub="4, 4, 1", level=-0.3, probes=probes, cycles=3)
     for name, shape in (("builtin", "set Shape = L-shape"),
                         ("file", "set Shape = mesh file\n  set Mesh file = " + mesh))}
b, f = L["builtin"][-1], L["file"][-1]
close(f["contact_force"], b["contact_force"], 1e-9, "3D L-shape: reaction, mesh file vs built-in")
for j in range(3):
    close(f["probes"][j], b["probes"][j], 1e-9, "3D L-shape: probe %d, mesh file vs built-in" % j)
finish()
