"""Loads on regions of a mesh ('Load/Region loads'), in every model: a Gmsh
mesh of [0, 10]^2 in 8 x 8 cells whose central square [2.5, 7.5]^2 has the
material id 1 and the rest the id 2 (the paper's plate, clamped, the plane
z = -0.05 below; the plates 8^2 -> 32^2 cells, the 3D body 8^2 -> 16^2 x 1).

- 'Region loads = 1: -0.02; 2: -0.001' equals the function load that is
  -0.02 on the square and -0.001 outside (the mesh follows the square's
  edges, so every quadrature point sees the same load; the Mindlin plate's
  'gsv' takes the load at its contact points on the cell edges as the
  limit from inside the cell): the same reaction
  and probes to 1e-10, and so does 'Transverse load = -0.001' with
  'Region loads = 1: -0.019' (a region load adds to the function).
- The total load in the plate models' summary.json is -0.02 * 25 - 0.001
  * 75 = -0.575."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, close, finish, write_msh

args = parse_args()
os.makedirs(args.workdir, exist_ok=True)
mesh = os.path.join(args.workdir, "two_regions.msh")
inside = lambda x, y: 2.5 < x < 7.5 and 2.5 < y < 7.5
write_msh(mesh, 10.0, 10.0, 8, 8, lambda x, y: False, None,
          lambda x, y: 1 if inside(x, y) else 2)

TEMPLATE = """set Model = %(model)s
subsection Geometry
  set Shape = mesh file
  set Mesh file = %(mesh)s
  set Subdivisions = %(sub)s
  set Number of cycles = %(cycles)d
end
subsection Load
  set Transverse load = %(load)s
  set Region loads = %(regions)s
end
subsection Obstacle
  set Level = -0.05
end
subsection Elasticity
  set Refine through thickness = false
end
subsection Output
  set Probe points = 5, 5; 2, 5; 5, 8; 1, 1
end
"""
LOADS = {"regions": ("0", "1: -0.02; 2: -0.001"),
         "function": ("(x > 2.5 && x < 7.5 && y > 2.5 && y < 7.5) ? -0.02 : -0.001", ""),
         "sum": ("-0.001", "1: -0.019")}
for model in ("membrane", "mindlin", "kirchhoff", "elasticity"):
    runs = {}
    for name, (load, regions) in LOADS.items():
        s, _ = run(args, "%s_%s" % (model, name),
                   TEMPLATE % dict(model=model, mesh=mesh, load=load, regions=regions,
                                   sub="8, 8, 1" if model == "elasticity" else "8, 8",
                                   cycles=2 if model == "elasticity" else 3),
                   pinned="rigid")
        check(all(c["converged"] for c in s["cycles"]), "%s %s: every cycle converged"
              % (model, name))
        runs[name] = s
    a = runs["function"]["cycles"][-1]
    check(a["contact_force"] > 0, "%s: the plate touches the plane (reaction %.6f)"
          % (model, a["contact_force"]))
    for name in ("regions", "sum"):
        b = runs[name]["cycles"][-1]
        close(b["contact_force"], a["contact_force"], 1e-10,
              "%s: reaction, '%s' vs the function load" % (model, name))
        for j in range(4):
            close(b["probes"][j], a["probes"][j], 1e-10,
                  "%s: probe %d, '%s' vs the function load" % (model, j, name))
    if model != "elasticity":  # (the plate models report it)
        close(runs["regions"]["cycles"][-1]["extra"]["load_total"], -0.575, 1e-10,
              "%s: the total load" % model)
finish()
