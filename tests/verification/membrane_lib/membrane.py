"""Parameter text shared by the membrane_* verification scripts (a helper
module in a subfolder, so that the CMake glob does not run it as a test)."""


def membrane_prm(lx=1.0, ly=1.0, sub=(4, 4), refinement=0, cycles=1,
                 edges="all: clamped", load="1",
                 obstacle="set Type = plane\n  set Level = -1e6", tension=1.0,
                 degree=1, alpha=0.01, rule="gauss", points=3, theta=1,
                 scheme="newton", probes="0.5, 0.5", exact="", compliance="0", extra=""):
    return f"""set Model = membrane
subsection Geometry
  set Length x = {lx!r}
  set Length y = {ly!r}
  set Boundary conditions = {edges}
  set Subdivisions = {sub[0]}, {sub[1]}
  set Initial refinement = {refinement}
  set Number of cycles = {cycles}
end
subsection Load
  set Transverse load = {load}
end
subsection Obstacle
  {obstacle}
end
subsection Contact
  set Nitsche theta = {theta}
  set Obstacle compliance = {compliance}
end
subsection Membrane
  set Tension = {tension!r}
  set Element degree = {degree}
  set Stabilisation alpha = {alpha!r}
  set Contact quadrature rule = {rule}
  set Contact quadrature points = {points}
end
subsection Nonlinear solver
  set Scheme = {scheme}
  set Tolerance = 1e-9
  set Maximum iterations = 100
  set Print iterations = true
end
subsection Reference solution
  set Exact solution = {exact}
end
subsection Output
  set Probe points = {probes}
  set Profile points = 11
end
{extra}
"""
