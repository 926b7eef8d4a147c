"""Parameter text shared by the kirchhoff_* verification scripts (a helper
module in a subfolder, so that the CMake glob does not run it as a test)."""

# E chosen so that D = E t^3 / (12 (1 - nu^2)) = 1 with t = 0.01, nu = 0.3.
E_UNIT_D = 12 * (1 - 0.3 ** 2) / 0.01 ** 3


def plate_prm(lx=1.0, ly=1.0, sub=(8, 8), cycles=1, edges="all: clamped",
              load="1", level=-1e6, convention="mid-plane", theta=1, alpha=1e-4, kappa=0.0,
              formulation="gsv", scheme="newton", probes="0.5, 0.5", extra=""):
    return f"""set Model = kirchhoff
subsection Geometry
  set Length x = {lx}
  set Length y = {ly}
  set Thickness = 0.01
  set Boundary conditions = {edges}
  set Subdivisions = {sub[0]}, {sub[1]}
  set Number of cycles = {cycles}
end
subsection Material
  set Young's modulus = {E_UNIT_D!r}
  set Poisson ratio = 0.3
end
subsection Load
  set Transverse load = {load}
end
subsection Obstacle
  set Type = plane
  set Level = {level!r}
  set Plate obstacle convention = {convention}
end
subsection Contact
  set Nitsche theta = {theta}
  set Obstacle compliance = {kappa!r}
end
subsection Kirchhoff
  set Contact formulation = {formulation}
  set Stabilisation alpha = {alpha!r}
end
subsection Nonlinear solver
  set Scheme = {scheme}
  set Tolerance = 1e-8
  set Maximum iterations = 200
  set Print iterations = false
end
subsection Output
  set Probe points = {probes}
  set Profile points = 11
end
{extra}
"""
