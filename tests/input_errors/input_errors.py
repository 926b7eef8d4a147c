"""Bad input must give exit status 1 and one clear message on stderr that
names the entry and the offending value (and, for range errors, what is
allowed); --help and --print-parameters must exit 0. No output directory
may be created for a rejected parameter file."""
import argparse
import json
import os
import resource
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "verification"))
from common import write_msh  # noqa: E402

p = argparse.ArgumentParser()
p.add_argument("--exe", required=True)
p.add_argument("--workdir", required=True)
args = p.parse_args()
os.makedirs(args.workdir, exist_ok=True)
failures = []


def check(ok, message):
    print(("ok    " if ok else "FAIL  ") + message)
    if not ok:
        failures.append(message)


def execute(argv):
    return subprocess.run([args.exe] + argv, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, cwd=args.workdir)


# (case, prm body, substrings the message must contain)
CASES = [
    ("unknown entry", "subsection Material\n  set Youngs modulus = 1\nend",
     ["'Material/Youngs modulus'", "line 10", "did you mean 'Young's modulus'"]),
    ("misspelled subsection", "subsection Materail\n\n  set Poisson ratio = 0.3\nend",
     ["unknown subsection 'Materail'", "line 9", "did you mean 'Material'"]),
    ("unknown top-level entry", "set Modell = elasticity", ["Modell"]),
    ("two-level solver, two cell layers",
     "subsection Geometry\n  set Subdivisions = 4, 4, 2\nend\n"
     "subsection Elasticity\n  subsection Linear solver\n    set Type = two-level\n  end\nend",
     ["Elasticity/Linear solver/Type", "'two-level'", "one cell through the thickness", "2 cells in x3"]),
    ("two-level solver, refinement through the thickness",
     "subsection Geometry\n  set Number of cycles = 2\nend\n"
     "subsection Elasticity\n  subsection Linear solver\n    set Type = two-level\n  end\n"
     "  set Refine through thickness = true\nend",
     ["Elasticity/Linear solver/Type", "'two-level'", "Refine through thickness"]),
    ("two-level solver, hanging nodes",
     "subsection Elasticity\n  subsection Linear solver\n    set Type = two-level\n  end\n"
     "  set Refinement box = 0, 0, -1; 1, 1, 1\n  set Local refinement steps = 1\nend",
     ["Elasticity/Linear solver/Type", "'two-level'", "hanging nodes", "Refinement box"]),
    ("E = 0", "subsection Material\n  set Young's modulus = 0\nend",
     ["Young's modulus", "'0'", "> 0"]),
    ("E < 0", "subsection Material\n  set Young's modulus = -2e5\nend",
     ["Young's modulus", "-200000", "> 0"]),
    ("E not a number", "subsection Material\n  set Young's modulus = abc\nend",
     ["Young's modulus", "abc"]),
    ("nu = 0.5", "subsection Material\n  set Poisson ratio = 0.5\nend",
     ["Poisson ratio", "0.5", "(-1, 0.5)"]),
    ("nu = -1", "subsection Material\n  set Poisson ratio = -1\nend",
     ["Poisson ratio", "'-1'", "(-1, 0.5)"]),
    ("nu > 0.5", "subsection Material\n  set Poisson ratio = 0.7\nend",
     ["Poisson ratio", "0.7", "(-1, 0.5)"]),
    ("thickness = 0", "subsection Geometry\n  set Thickness = 0\nend",
     ["Thickness", "'0'", "> 0"]),
    ("thickness < 0", "subsection Geometry\n  set Thickness = -0.01\nend",
     ["Thickness", "-0.01", "> 0"]),
    ("F < 0", "subsection Contact\n  set Friction coefficient = -0.2\nend",
     ["Friction coefficient", "-0.2", ">= 0"]),
    ("gamma0 = 0", "subsection Contact\n  set Nitsche gamma0 = 0\nend",
     ["Nitsche gamma0", "'0'", "> 0"]),
    ("gamma0 < 0", "subsection Contact\n  set Nitsche gamma0 = -5\nend",
     ["Nitsche gamma0", "-5", "> 0"]),
    ("theta = 0.5", "subsection Contact\n  set Nitsche theta = 0.5\nend",
     ["Nitsche theta", "0.5", "1, 0, -1"]),
    ("theta = 2", "subsection Contact\n  set Nitsche theta = 2\nend",
     ["Nitsche theta", "'2'", "1, 0, -1"]),
    ("unknown model", "set Model = elastic", ["Model", "elastic", "kirchhoff"]),
    ("malformed probe list", "subsection Output\n  set Probe points = 1, 2; 3\nend",
     ["Probe points", "1, 2; 3"]),
    ("probe not numbers", "subsection Output\n  set Probe points = a, b\nend",
     ["Probe points", "a, b"]),
    ("unknown obstacle", "subsection Obstacle\n  set Type = cone\nend",
     ["Obstacle/Type", "cone", "sphere"]),
    ("Kirchhoff Krylov tolerance = 0",
     "set Model = kirchhoff\nsubsection Kirchhoff\n  subsection Linear solver\n"
     "    set Type = multigrid\n    set Krylov tolerance = 0\n  end\nend",
     ["Kirchhoff/Linear solver/Krylov tolerance", "'0'", "(0, 1)"]),
    ("Kirchhoff multigrid with the nitsche formulation",
     "set Model = kirchhoff\nsubsection Kirchhoff\n  subsection Linear solver\n"
     "    set Type = multigrid\n  end\n  set Contact formulation = nitsche\nend",
     ["Kirchhoff/Linear solver/Type", "multigrid", "gsv", "direct"]),
    ("Mindlin Krylov tolerance = 0",
     "set Model = mindlin\nsubsection Mindlin\n  subsection Linear solver\n    set Type = multigrid\n"
     "    set Krylov tolerance = 0\n  end\nend",
     ["Mindlin/Linear solver/Krylov tolerance", "'0'", "(0, 1)"]),
    ("Mindlin linear solver entry of the old layout",
     "set Model = mindlin\nsubsection Mindlin\n  set Linear solver = multigrid\nend",
     ["Mindlin/Linear solver", "no longer exists", "'Type'", "'Direct solver'"]),
    ("elasticity tangential traction on a plate free in its plane",
     "subsection Geometry\n  set Boundary conditions = all: free\nend\n"
     "subsection Obstacle\n  set Level = 0.5\nend\n"
     "subsection Elasticity\n  set Top tangential traction = 0.001; 0\nend",
     ["Elasticity/Top tangential traction", "'0.001; 0'", "no resultant", "x1 component"]),
    ("local refinement of the whole body beyond 1e7 cells",
     "subsection Elasticity\n  set Refinement box = -1, -1, -1; 11, 11, 1\n"
     "  set Local refinement steps = 10\nend",
     ["Elasticity/Local refinement steps", "'10'", "100 % of the body", "1e7"]),
    # a load that is not finite in a band between the points of the
    # 101 x 101 grid check, but at a quadrature point of the assembly
    ("3D load not finite at a quadrature point",
     "subsection Load\n  set Transverse load = -0.02 + 0*sqrt((x-1.127)^2 - 1e-6)\nend",
     ["Load/Transverse load", "quadrature point (1.127"]),
    ("3D tangential traction not finite at a quadrature point",
     "subsection Elasticity\n  set Top tangential traction = 0*sqrt((x-1.127)^2 - 1e-6); 0\nend",
     ["Elasticity/Top tangential traction", "quadrature point (1.127"]),
    ("Kirchhoff load not finite at a quadrature point",
     "set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 8, 8\nend\n"
     "subsection Load\n  set Transverse load = -0.02 + 0*sqrt((x-5.0422)^2 - 1e-6)\nend",
     ["Load/Transverse load", "quadrature point (5.0422"]),
    ("Mindlin load not finite at a quadrature point",
     "set Model = mindlin\nsubsection Geometry\n  set Subdivisions = 8, 8\nend\n"
     "subsection Load\n  set Transverse load = -0.02 + 0*sqrt((x-5.2641)^2 - 1e-6)\nend",
     ["Load/Transverse load", "quadrature point (5.264"]),
    ("elasticity Krylov tolerance = 0",
     "subsection Elasticity\n  subsection Linear solver\n    set Type = amg\n"
     "    set Krylov tolerance = 0\n  end\nend",
     ["Elasticity/Linear solver/Krylov tolerance", "'0'", "(0, 1)"]),
    ("moved entry 'Elasticity/Linear solver'",
     "subsection Elasticity\n  set Linear solver = amg\nend",
     ["Elasticity/Linear solver", "no longer exists", "'Type'"]),
    ("moved entry 'Elasticity/Krylov tolerance'",
     "subsection Elasticity\n  set Krylov tolerance = 1e-8\nend",
     ["Elasticity/Krylov tolerance", "no longer exists", "'Elasticity/Linear solver'"]),
    ("elasticity factorisation reuse not a bool",
     "subsection Elasticity\n  subsection Linear solver\n"
     "    set Reuse factorization = sometimes\n  end\nend",
     ["Reuse factorization", "sometimes", "'true' and 'false'"]),
    ("load constant named like a variable",
     "subsection Load\n  set Function constants = x=1\nend",
     ["Load/Function constants", "x=1", "'x' is not"]),
    ("load constant defined twice",
     "subsection Load\n  set Function constants = q=1, q=2\nend",
     ["Load/Function constants", "q=1, q=2", "'q' is defined twice"]),
    ("load not finite on the plate",
     "subsection Load\n  set Transverse load = sqrt(x-20)\nend",
     ["Load/Transverse load", "sqrt(x-20)", "finite number", "[0, 10] x [0, 10]"]),
    ("obstacle height not finite on part of the plate",
     "subsection Obstacle\n  set Type = function\n  set Height = sqrt(25-(x-5)^2-(y-5)^2) - 6\nend",
     ["Obstacle/Height", "sqrt(25-(x-5)^2-(y-5)^2) - 6", "at (0, 0)", "finite number"]),
    ("obstacle height syntax error",
     "subsection Obstacle\n  set Type = function\n  set Height = -1 +* x\nend",
     ["Obstacle/Height", "-1 +* x", "could not be parsed"]),
    ("probe point outside the plate",
     "subsection Output\n  set Probe points = 5, 5; 15, 5\nend",
     ["Output/Probe points", "5, 5; 15, 5", "(15, 5)", "outside the plate"]),
    ("profile line leaves the plate",
     "subsection Output\n  set Profile line = -5, 5; 15, 5\nend",
     ["Output/Profile line", "-5, 5; 15, 5", "outside the plate"]),
    ("profile line of zero length",
     "subsection Output\n  set Profile line = 5, 5; 5, 5\nend",
     ["Output/Profile line", "5, 5; 5, 5", "must differ"]),
    ("profile line 'centre'",
     "subsection Output\n  set Profile line = centre\nend",
     ["Output/Profile line", "'centre'", "'centre line' or two points"]),
    ("profile line of three numbers",
     "subsection Output\n  set Profile line = 1, 2, 3\nend",
     ["Output/Profile line", "'1, 2, 3'", "'centre line' or two points"]),
    ("tolerance = 0", "subsection Nonlinear solver\n  set Tolerance = 0\nend",
     ["Nonlinear solver/Tolerance", "'0'", "(0, 1)"]),
    ("tolerance = 2", "subsection Nonlinear solver\n  set Tolerance = 2\nend",
     ["Nonlinear solver/Tolerance", "'2'", "(0, 1)"]),
    # the boundary
    ("tolerance = 1", "subsection Nonlinear solver\n  set Tolerance = 1\nend",
     ["Nonlinear solver/Tolerance", "'1'", "(0, 1)"]),
    ("trailing comma in the load constants",
     "subsection Load\n  set Function constants = q0=1,\nend",
     ["Load/Function constants", "q0=1,", "an empty pair"]),
    ("doubled comma in the load constants",
     "subsection Load\n  set Function constants = a=1,,b=2\nend",
     ["Load/Function constants", "a=1,,b=2", "an empty pair"]),
    ("obstacle height naming a constant (it has none)",
     "subsection Obstacle\n  set Type = function\n  set Height = h0\nend\n"
     "subsection Reference solution\n  set Function constants = h0=-1\nend",
     ["Obstacle/Height", "'h0'", "variables are x,y, plus pi)"]),
    ("malformed reference constants without an exact solution",
     "subsection Reference solution\n  set Function constants = a=1, b\nend",
     ["Reference solution/Function constants", "a=1, b", "'name=value'"]),
    ("local refinement without a box",
     "subsection Elasticity\n  set Local refinement steps = 2\nend",
     ["Elasticity/Local refinement steps", "'2'", "Refinement box"]),
    ("first mesh too large",
     "subsection Geometry\n  set Subdivisions = 100000, 100000, 1\nend",
     ["Geometry/Subdivisions", "100000, 100000, 1", "1e7 cells"]),
    ("field grid of one point",
     "subsection Output\n  set Field grid points = 1\nend",
     ["Output/Field grid points", "'1'", "at least 2"]),
    ("Mindlin multigrid with friction",
     "set Model = mindlin\nsubsection Contact\n  set Friction coefficient = 0.2\nend\n"
     "subsection Mindlin\n  subsection Linear solver\n    set Type = multigrid\n  end\nend",
     ["Mindlin/Linear solver/Type", "multigrid", "Friction coefficient"]),
    ("Mindlin multigrid with MITC9",
     "set Model = mindlin\nsubsection Mindlin\n  subsection Linear solver\n    set Type = multigrid\n  end\n"
     "  set Shear treatment = MITC9\nend",
     ["Mindlin/Linear solver/Type", "multigrid", "MITC9", "Type = direct"]),
    ("full shear with the equilibrium contact stress",
     "set Model = mindlin\nsubsection Mindlin\n  set Shear treatment = full\nend",
     ["Mindlin/Shear treatment", "'full'", "Contact formulation = nitsche"]),
    ("MITC9 with 2 contact points per direction",
     "set Model = mindlin\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Mindlin\n  set Shear treatment = MITC9\n"
     "  set Contact quadrature rule = lobatto\n  set Contact quadrature points = 2\nend",
     ["Mindlin/Contact quadrature points", "'2'", "MITC9", "at least 3"]),
    ("Mindlin multigrid on an odd number of cells",
     "set Model = mindlin\nsubsection Geometry\n  set Subdivisions = 5, 4\nend\n"
     "subsection Mindlin\n  subsection Linear solver\n    set Type = multigrid\n  end\nend",
     ["Mindlin/Linear solver/Type", "multigrid", "even", "5, 4"]),
    ("Kirchhoff unknown linear solver",
     "set Model = kirchhoff\nsubsection Kirchhoff\n  subsection Linear solver\n"
     "    set Type = amg\n  end\nend",
     ["Type", "amg", "multigrid"]),
    ("Kirchhoff moved entry 'Linear solver'",
     "set Model = kirchhoff\nsubsection Kirchhoff\n  set Linear solver = multigrid\nend",
     ["Kirchhoff/Linear solver", "no longer exists", "'Type'"]),
    ("Kirchhoff moved entry 'Direct solver'",
     "set Model = kirchhoff\nsubsection Kirchhoff\n  set Direct solver = Amesos_Klu\nend",
     ["Kirchhoff/Direct solver", "no longer exists", "Kirchhoff/Linear solver"]),
    ("Gauss-Lobatto contact rule with one point",
     "subsection Elasticity\n  set Contact quadrature points = 1\n"
     "  set Contact quadrature rule = lobatto\nend",
     ["Elasticity/Contact quadrature points", "'1'", "at least 2"]),
    ("unknown contact quadrature rule",
     "set Model = mindlin\nsubsection Mindlin\n  set Contact quadrature rule = simpson\nend",
     ["Contact quadrature rule", "simpson", "lobatto"]),
    ("moved entry 'Nonlinear solver/Reuse factorization'",
     "subsection Nonlinear solver\n  set Reuse factorization = false\nend",
     ["Nonlinear solver/Reuse factorization", "no longer exists", "'Linear solver'"]),
    ("moved entry 'Nonlinear solver/Symmetric factorization'",
     "subsection Nonlinear solver\n  set Symmetric factorization = true\nend",
     ["Nonlinear solver/Symmetric factorization", "no longer exists", "'Linear solver'"]),
    ("in-plane refinement with local refinement",
     "subsection Geometry\n  set Number of cycles = 2\nend\n"
     "subsection Elasticity\n  set Refine through thickness = false\n"
     "  set Refinement box = 0, 0, -1; 1, 1, 1\n  set Local refinement steps = 1\nend",
     ["Elasticity/Refine through thickness", "'false'", "Local refinement steps", "= 1"]),
    ("sphere centre not finite",
     "subsection Obstacle\n  set Type = sphere\n  set Sphere center = nan, 5, -3\nend",
     ["Obstacle/Sphere center", "nan, 5, -3", "finite decimal numbers"]),
    ("subdivisions in hexadecimal",
     "subsection Geometry\n  set Subdivisions = 0x2, 2, 1\nend",
     ["Geometry/Subdivisions", "0x2, 2, 1", "finite decimal numbers"]),
    ("refinement box with trailing text",
     "subsection Elasticity\n  set Refinement box = 0, 0, -1abc; 5, 5, 1\n"
     "  set Local refinement steps = 1\nend",
     ["Elasticity/Refinement box", "-1abc", "finite decimal numbers"]),
    ("refinement box without a cell",
     "subsection Elasticity\n  set Refinement box = 100, 100, -1; 200, 200, 1\n"
     "  set Local refinement steps = 1\nend",
     ["Elasticity/Refinement box", "no cell centre", "nothing would be refined"]),
    ("top traction on a clamped top face",
     "subsection Elasticity\n  set Top face = clamped\n  set Load applied as = top traction\nend",
     ["Elasticity/Load applied as", "top traction", "clamped"]),
    ("tangential traction on a clamped top face",
     "subsection Elasticity\n  set Top face = clamped\n  set Top tangential traction = 100; 0\nend",
     ["Elasticity/Top tangential traction", "100; 0", "clamped"]),
    ("plate predictor with a clamped top face",
     "subsection Elasticity\n  set Top face = clamped\n  set Plate predictor = true\nend",
     ["Elasticity/Plate predictor", "'true'", "Top face = free"]),
    ("plate predictor with load steps",
     "subsection Nonlinear solver\n  set Load steps = 3\nend\n"
     "subsection Elasticity\n  set Plate predictor = true\nend",
     ["Elasticity/Plate predictor", "'true'", "Load steps' = 3", "Load steps = 1"]),
    ("plate predictor with local refinement",
     "subsection Elasticity\n  set Refinement box = 0, 0, -1; 1, 1, 1\n"
     "  set Local refinement steps = 1\n  set Plate predictor = true\nend",
     ["Elasticity/Plate predictor", "'true'", "Refinement box"]),
    ("tangential traction not finite",
     "subsection Elasticity\n  set Top tangential traction = 0; sqrt(x-20)\nend",
     ["Elasticity/Top tangential traction", "sqrt(x-20)", "finite number"]),
    ("exact solution not finite",
     "subsection Reference solution\n  set Exact solution = 0; 0; log(x-20)\nend",
     ["Reference solution/Exact solution", "log(x-20)", "finite number"]),
    ("Kirchhoff exact gradient not finite",
     "set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 4, 4\nend\n"
     "subsection Reference solution\n  set Exact solution = 0\nend\n"
     "subsection Kirchhoff\n  set Exact gradient = 0; sqrt(-1)\nend",
     ["Kirchhoff/Exact gradient", "sqrt(-1)", "finite number"]),
    ("membrane tension = 0",
     "set Model = membrane\nsubsection Membrane\n  set Tension = 0\nend",
     ["Membrane/Tension", "'0'", "> 0"]),
    ("membrane stabilisation alpha = 0",
     "set Model = membrane\nsubsection Membrane\n  set Stabilisation alpha = 0\nend",
     ["Membrane/Stabilisation alpha", "'0'", "> 0"]),
    ("membrane with friction",
     "set Model = membrane\nsubsection Contact\n  set Friction coefficient = 0.2\nend",
     ["Contact/Friction coefficient", "0.2", "frictionless"]),
    ("membrane with cells through a thickness",
     "set Model = membrane\nsubsection Geometry\n  set Subdivisions = 4, 4, 4\nend",
     ["Geometry/Subdivisions", "4, 4, 4", "membrane"]),
    ("membrane load not finite at a quadrature point",
     "set Model = membrane\nsubsection Geometry\n  set Subdivisions = 8, 8\nend\n"
     "subsection Load\n  set Transverse load = -0.02 + 0*sqrt((x-5.1409)^2 - 1e-6)\nend",
     ["Load/Transverse load", "quadrature point (5.14"]),
    ("Kirchhoff with cells through the thickness",
     "set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 4, 4, 4\nend",
     ["Geometry/Subdivisions", "4, 4, 4", "no cells through the thickness"]),
    ("obstacle height not finite between the grid points of the input check",
     "subsection Geometry\n  set Subdivisions = 8, 8, 1\nend\n"
     "subsection Obstacle\n  set Type = function\n"
     "  set Height = -1 + 0*sqrt((x-5.05)^2 - 0.0016)\nend\n"
     # Gauss points, one of which lies in the strip |x - 5.05| < 0.04
     "subsection Elasticity\n  set Contact quadrature rule = gauss\nend",
     ["Obstacle/Height", "sqrt((x-5.05)^2 - 0.0016)", "not a finite number at",
      "contact quadrature point"]),
    ("Young's modulus overflowing the stiffness",
     "subsection Material\n  set Young's modulus = 1e305\nend",
     ["Young's modulus", "1e+305", "overflow"]),
    ("Young's modulus underflowing the stiffness",
     "subsection Material\n  set Young's modulus = 1e-300\nend",
     ["Young's modulus", "1e-300", "underflow", "bending stiffness"]),
    ("Mindlin load overflowing the contact force scale",
     "set Model = mindlin\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Load\n  set Transverse load = -1e300\nend",
     ["Load/Transverse load", "1e+300", "overflow"]),
    ("gamma0 overflowing the contact force scale",
     "subsection Contact\n  set Nitsche gamma0 = 1e300\nend",
     ["Contact/Nitsche gamma0", "1e+300", "overflow"]),
    ("Kirchhoff with Nitsche: gamma0 overflowing the contact force scale",
     "set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Kirchhoff\n  set Contact formulation = nitsche\nend\n"
     "subsection Contact\n  set Nitsche gamma0 = 1e300\nend",
     ["Contact/Nitsche gamma0", "1e+300", "overflow"]),
    ("top traction naming a constant (it has none)",
     "subsection Elasticity\n  set Top tangential traction = q0; 0\nend\n"
     "subsection Load\n  set Function constants = q0=1\nend",
     ["Elasticity/Top tangential traction", "q0; 0", "plus pi)"]),
    ("degenerate side ratio",
     "subsection Geometry\n  set Length x = 1e20\nend",
     ["Geometry/Length x", "1e+20", "Geometry/Length y", "[1e-6, 1e6]"]),
    ("Length x = 0", "subsection Geometry\n  set Length x = 0\nend",
     ["Geometry/Length x", "'0'", "> 0"]),
    ("Length y < 0", "subsection Geometry\n  set Length y = -3\nend",
     ["Geometry/Length y", "-3", "> 0"]),
    ("the replaced entry Edge conditions",
     "subsection Geometry\n  set Edge conditions = clamped, clamped, free, free\nend",
     ["Geometry/Edge conditions", "no longer exists", "Geometry/Boundary conditions"]),
    ("boundary condition without id",
     "subsection Geometry\n  set Boundary conditions = 0 clamped\nend",
     ["Geometry/Boundary conditions", "'0 clamped'", "id: condition"]),
    ("unknown boundary condition",
     "subsection Geometry\n  set Boundary conditions = 0: glued; all: free\nend",
     ["Geometry/Boundary conditions", "'glued' is no condition", "simply supported"]),
    ("boundary id the mesh does not have",
     "subsection Geometry\n  set Boundary conditions = 5: free; all: clamped\nend",
     ["Geometry/Boundary conditions", "no boundary id 5", "0, 1, 2, 3"]),
    ("boundary id without a condition",
     "subsection Geometry\n  set Boundary conditions = 0: clamped; 1: free\nend",
     ["Geometry/Boundary conditions", "boundary id 2", "has no condition"]),
    ("a plate model on a disk",
     "set Model = kirchhoff\nsubsection Geometry\n  set Shape = disk\nend",
     ["Geometry/Shape", "'disk'", "'rectangle with hole' and 'mesh file' only",
      "Mindlin and the membrane"]),
    ("the 3D model with symmetry on a disk",
     "subsection Geometry\n  set Shape = disk\n  set Subdivisions = 2, 2, 1\n"
     "  set Boundary conditions = all: symmetry\nend",
     ["Geometry/Boundary conditions", "all: symmetry", "ids 0 to 3", "not on the id 0",
      "Mindlin model"]),
    ("the 3D model with symmetry on the L-shape's inner edges",
     "subsection Geometry\n  set Shape = L-shape\n  set Subdivisions = 2, 2, 1\n"
     "  set Boundary conditions = 4: symmetry; all: clamped\nend",
     ["Geometry/Boundary conditions", "4: symmetry; all: clamped", "ids 0 to 3",
      "not on the id 4"]),
    ("annulus inner radius above the radius",
     "set Model = membrane\nsubsection Geometry\n  set Shape = annulus\n"
     "  set Radius = 2\n  set Inner radius = 3\nend",
     ["Geometry/Inner radius", "'3'", "(0, Radius)"]),
    ("hole off the grid lines",
     "set Model = membrane\nsubsection Geometry\n  set Shape = rectangle with hole\n"
     "  set Hole size = 3, 3\n  set Subdivisions = 8, 8\nend",
     ["Geometry/Hole size", "'3, 3'", "lines of the coarse grid"]),
    ("L-shape with an odd number of cells",
     "set Model = membrane\nsubsection Geometry\n  set Shape = L-shape\n"
     "  set Subdivisions = 7, 8\nend",
     ["Geometry/Subdivisions", "'7, 8'", "even"]),
    ("missing mesh file",
     "set Model = membrane\nsubsection Geometry\n  set Shape = mesh file\n"
     "  set Mesh file = no_such_mesh.msh\nend",
     ["Geometry/Mesh file", "no_such_mesh.msh", "cannot be read"]),
    ("mesh file of an unknown format",
     "set Model = membrane\nsubsection Geometry\n  set Shape = mesh file\n"
     "  set Mesh file = case00.prm\nend",
     ["Geometry/Mesh file", "case00.prm", "Gmsh (.msh)"]),
    ("probe outside the disk",
     "set Model = membrane\nsubsection Geometry\n  set Shape = disk\nend\n"
     "subsection Output\n  set Probe points = 0.5, 0.5\nend",
     ["Output/Probe points", "(0.5, 0.5)", "outside the plate", "disk"]),
    ("one subdivision count", "subsection Geometry\n  set Subdivisions = 8\nend",
     ["Geometry/Subdivisions", "'8'", "nx, ny"]),
    ("sphere radius 0",
     "subsection Obstacle\n  set Type = sphere\n  set Sphere radius = 0\nend",
     ["Obstacle/Sphere radius", "'0'", "> 0"]),
    ("sphere centre with two coordinates",
     "subsection Obstacle\n  set Type = sphere\n  set Sphere center = 5, 5\nend",
     ["Obstacle/Sphere center", "5, 5", "x, y, z"]),
    ("empty output directory", "subsection Output\n  set Directory =\nend",
     ["Output/Directory", "must not be empty"]),
    ("refinement box with one corner",
     "subsection Elasticity\n  set Refinement box = 0, 0, 0\nend",
     ["Refinement box", "0, 0, 0", "two corners"]),
    ("Mindlin shear correction factor 0",
     "set Model = mindlin\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Mindlin\n  set Shear correction factor = 0\nend",
     ["Mindlin/Shear correction factor", "'0'", "> 0"]),
    ("Mindlin without membrane unknowns but with friction",
     "set Model = mindlin\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Contact\n  set Friction coefficient = 0.2\nend\n"
     "subsection Mindlin\n  set Membrane unknowns = false\nend",
     ["Mindlin/Membrane unknowns", "false", "Friction coefficient"]),
    ("Kirchhoff with friction",
     "set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Contact\n  set Friction coefficient = 0.2\nend",
     ["Contact/Friction coefficient", "0.2"]),
    ("Kirchhoff alpha < 0",
     "set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Kirchhoff\n  set Stabilisation alpha = -1e-4\nend",
     ["Stabilisation alpha", "-1e-4", ">= 0"]),
    ("obstacle compliance < 0",
     "subsection Contact\n  set Obstacle compliance = -1e-5\nend",
     ["Contact/Obstacle compliance", "-1e-5", "'auto' or a number >= 0"]),
    ("obstacle compliance not a number",
     "subsection Contact\n  set Obstacle compliance = soft\nend",
     ["Contact/Obstacle compliance", "soft", "'auto' or a number >= 0"]),
    ("Kirchhoff compliance entry of the old layout",
     "set Model = kirchhoff\nsubsection Kirchhoff\n  set Obstacle compliance kappa = 1e-6\nend",
     ["Kirchhoff/Obstacle compliance kappa", "no longer exists", "'Obstacle compliance'",
      "'Contact'"]),
    ("Kirchhoff pure penalty on a rigid obstacle",
     "set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Kirchhoff\n  set Stabilisation alpha = 0\nend\n"
     "subsection Contact\n  set Obstacle compliance = 0\nend",
     ["Kirchhoff/Stabilisation alpha", "'0'", "Contact/Obstacle compliance"]),
    ("Kirchhoff exact gradient without an exact solution",
     "set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 2, 2\nend\n"
     "subsection Kirchhoff\n  set Exact gradient = x; y\nend",
     ["Kirchhoff/Exact gradient", "x; y", "Exact solution"]),
]

# a regular file: a directory below it can never be created (even as root)
blocker = os.path.join(args.workdir, "a_regular_file")
with open(blocker, "w") as f:
    f.write("not a directory\n")
CASES += [
    ("bulk fraction 0", "set Model = membrane\nsubsection Geometry\n  set Refinement = adaptive\n"
     "  set Bulk fraction = 0\nend", ["Geometry/Bulk fraction", "'0'", "(0, 1]"]),
    ("bulk fraction above 1", "set Model = membrane\nsubsection Geometry\n  set Bulk fraction = 1.5\nend",
     ["Geometry/Bulk fraction", "'1.5'", "(0, 1]"]),
    ("negative target estimate", "set Model = membrane\nsubsection Geometry\n"
     "  set Target relative error estimate = -0.01\nend",
     ["Geometry/Target relative error estimate", "'-0.01'", "positive number"]),
    ("13 global cycles", "set Model = membrane\nsubsection Geometry\n  set Number of cycles = 13\nend",
     ["Geometry/Number of cycles", "'13'", "at most 12", "Refinement = adaptive"]),
    ("adaptive Kirchhoff plate", "set Model = kirchhoff\nsubsection Geometry\n  set Refinement = adaptive\n"
     "  set Number of cycles = 2\nend",
     ["Geometry/Refinement", "'adaptive'", "'kirchhoff'", "allowed is 'global'", "membrane",
      "mindlin"]),
    ("adaptive Mindlin multigrid", "set Model = mindlin\nsubsection Geometry\n  set Subdivisions = 2, 2\n"
     "  set Refinement = adaptive\nend\nsubsection Mindlin\n  subsection Linear solver\n"
     "    set Type = multigrid\n  end\nend",
     ["Mindlin/Linear solver/Type", "'multigrid'", "uniform meshes", "Type = direct"]),
    ("target estimate without an estimator", "set Model = kirchhoff\nsubsection Geometry\n"
     "  set Target relative error estimate = 0.01\nend",
     ["Geometry/Target relative error estimate", "'0.01'", "'kirchhoff'", "no error estimator"]),
]
CASES.append(("unwritable output directory",
              "subsection Output\n  set Directory = %s/out\nend" % blocker,
              ["Output/Directory", blocker + "/out"]))

# a Gmsh mesh of the square [0, 10]^2 in two triangles
with open(os.path.join(args.workdir, "triangles.msh"), "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
            "1 0 0 0\n2 10 0 0\n3 10 10 0\n4 0 10 0\n$EndNodes\n"
            "$Elements\n2\n1 2 2 0 1 1 2 3\n2 2 2 0 1 1 3 4\n$EndElements\n")
CASES.append(("mesh file of triangles",
              "set Model = membrane\nsubsection Geometry\n  set Shape = mesh file\n"
              "  set Mesh file = triangles.msh\nend",
              ["Geometry/Mesh file", "triangles.msh", "not a quadrilateral",
               "at 6.66667, 3.33333"]))
# the Kirchhoff plate on mesh files: a cell that is not an axis-parallel
# rectangle (the shipped plate with a hole) and axis-parallel rectangles of
# different widths (x -> x^2/10 on a 4 x 4 grid)
hole_mesh = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                         "parameters", "meshes", "plate_with_hole.msh")
CASES.append(("Kirchhoff on a mesh file of general quadrilaterals",
              "set Model = kirchhoff\nsubsection Geometry\n  set Shape = mesh file\n"
              "  set Mesh file = %s\n  set Boundary conditions = all: clamped\nend" % hole_mesh,
              ["Geometry/Mesh file", "plate_with_hole.msh", "not an axis-parallel rectangle",
               "Model = mindlin"]))
write_msh(os.path.join(args.workdir, "graded.msh"), 10.0, 10.0, 4, 4, lambda x, y: False,
          lambda x, y: (x * x / 10, y))
CASES.append(("Kirchhoff on a mesh file of unequal rectangles",
              "set Model = kirchhoff\nsubsection Geometry\n  set Shape = mesh file\n"
              "  set Mesh file = graded.msh\nend",
              ["Geometry/Mesh file", "graded.msh", "(0.625 0), (2.5 0), (0.625 2.5), (2.5 2.5)",
               "is not of the size 0.625 x 2.5 of the mesh's first cell"]))
CASES.append(("the 3D plate predictor asked for with two load steps",
              "subsection Nonlinear solver\n  set Load steps = 2\nend\n"
              "subsection Elasticity\n  set Plate predictor = true\nend",
              ["Elasticity/Plate predictor", "'true'", "Load steps = 1"]))
CASES.append(("boundary id 1000 on the rectangle",
              "subsection Geometry\n  set Boundary conditions = 1000: free; "
              "all: clamped\nend",
              ["Geometry/Boundary conditions", "no boundary id 1000"]))

# obstacle data files: each defect is named with the file and its line
DATA_FILES = [
    ("data file, a row too short", "0 10 3\n0 10 2\n-1 -1 -1\n-1 -1\n",
     ["short.txt", "line 4", "2 values, expected n_x = 3"]),
    ("data file, a missing row", "# heights\n0 10 2\n0 10 3\n-1 -1\n-1 -1\n",
     ["missing.txt", "ends after 2 of its 3 rows"]),
    ("data file, a value that is not a number", "0 10 2\n0 10 2\n-1 abc\n-1 -1\n",
     ["letters.txt", "line 3", "'abc' is not a number"]),
    ("data file, a non-finite value", "0 10 2\n0 10 2\n-1 -1\n-1 nan\n",
     ["nan.txt", "line 4", "'nan' is not a finite number"]),
    ("data file, one point in x", "0 10 1\n0 10 2\n-1\n-1\n",
     ["one.txt", "line 1", "n_x = 1", "at least 2 points per direction"]),
    ("data file, an empty extent", "0 10 2\n5 5 2\n-1 -1\n-1 -1\n",
     ["flat.txt", "line 2", "y_max must exceed y_min"]),
    ("data file, an extra row", "0 10 2\n0 10 2\n-1 -1\n-1 -1\n-1 -1\n",
     ["extra.txt", "line 5", "more rows than n_y = 2"]),
]
for (case, text, expected), name in zip(DATA_FILES, ("short", "missing", "letters", "nan",
                                                     "one", "flat", "extra")):
    with open(os.path.join(args.workdir, name + ".txt"), "w") as f:
        f.write(text)
    CASES.append((case, "subsection Obstacle\n  set Type = data\n  set Data file = %s.txt\nend"
                  % name, ["obstacle data file", "error"] + expected))
with open(os.path.join(args.workdir, "hex.txt"), "w") as f:
    f.write("0 10 2\n0 10 2\n-1 -0x1p3\n-1 -1\n")
CASES.append(("data file, a hexadecimal number",
              "subsection Obstacle\n  set Type = data\n  set Data file = hex.txt\nend",
              ["obstacle data file 'hex.txt'", "line 3", "'-0x1p3' is not a number"]))
with open(os.path.join(args.workdir, "far.txt"), "w") as f:
    f.write("20 30 2\n20 30 2\n-1 -1\n-1 -1\n")
CASES.append(("data grid beside the plate",
              "subsection Obstacle\n  set Type = data\n  set Data file = far.txt\nend",
              ["Obstacle/Data file", "far.txt", "[20, 30] x [20, 30]", "does not reach the plate",
               "[0, 10] x [0, 10]"]))
CASES.append(("data obstacle without a file",
              "subsection Obstacle\n  set Type = data\nend",
              ["Obstacle/Data file", "needs a file"]))
CASES.append(("data obstacle file missing",
              "subsection Obstacle\n  set Type = data\n  set Data file = no_such_heights.txt\nend",
              ["Obstacle/Data file", "no_such_heights.txt", "cannot be read"]))
with open(os.path.join(args.workdir, "high.txt"), "w") as f:
    f.write("0 10 2\n0 10 2\n1 1\n1 1\n")
CASES.append(("data obstacle above the clamped edges",
              "subsection Obstacle\n  set Type = data\n  set Data file = high.txt\nend",
              ["Obstacle/Data file", "high.txt", "lies above the contact surface"]))
# region loads
CASES.append(("region load on a material id the mesh does not have",
              "subsection Load\n  set Region loads = 0: -0.01; 3: -0.02\nend",
              ["Load/Region loads", "0: -0.01; 3: -0.02", "no cells of material id 3",
               "material ids are 0"]))
CASES.append(("region load without a value",
              "subsection Load\n  set Region loads = 0:\nend",
              ["Load/Region loads", "0:"]))
CASES.append(("region load named twice",
              "subsection Load\n  set Region loads = 0: -1; 0: -2\nend",
              ["Load/Region loads", "named twice"]))
CASES.append(("region load id not a number",
              "subsection Load\n  set Region loads = plate: -1\nend",
              ["Load/Region loads", "'plate' is no material id"]))

# The syntax of the file itself (the body starts on line 9 of each file).
CASES.append(("subsection without end",
              "subsection Material\n  set Poisson ratio = 0.3",
              ["subsection 'Material'", "has no 'end'"]))
CASES.append(("end without subsection", "end",
              ["'end' without a subsection", "line 9"]))
CASES.append(("a line that is no statement",
              "subsection Material\n  Poisson ratio = 0.3\nend",
              ["line 10", "'Poisson ratio = 0.3'", "'set Name = value'"]))
CASES.append(("set without a value", "set Model elasticity",
              ["line 9", "has no '='"]))
CASES.append(("a file that includes itself",
              "include " + os.path.join(args.workdir, "case%02d.prm" % len(CASES)),
              ["includes itself"]))
CASES.append(("an included file that does not exist",
              "include " + os.path.join(args.workdir, "no_such_file.prm"),
              ["no_such_file.prm", "does not exist"]))

for i, (case, body, expected) in enumerate(CASES):
    prm = os.path.join(args.workdir, "case%02d.prm" % i)
    outdir = os.path.join(args.workdir, "case%02d-out" % i)
    shutil.rmtree(outdir, ignore_errors=True)  # of an earlier run of the test
    with open(prm, "w") as f:
        # a tiny valid problem, then the bad entry; the last 'set' wins
        f.write("set Model = elasticity\n"
                "subsection Geometry\n  set Subdivisions = 1, 1, 1\nend\n"
                "subsection Output\n  set Directory = %s\n  set Format = none\nend\n"
                % outdir)
        f.write(body + "\n")
    r = execute([prm])
    message = r.stderr.strip()
    check(r.returncode == 1, "%s: exit status %d == 1" % (case, r.returncode))
    missing = [s for s in expected if s not in message]
    check(not missing, "%s: message names %s: %s" % (case, expected, message.replace("\n", " ")[:300]))
    check("error" in message and "internal error" not in message,
          "%s: reported as an input error, not an internal error" % case)
    if case != "unwritable output directory":
        check(not os.path.exists(outdir), "%s: no output directory created" % case)

# A malformed XML parameter file (deal.II picks the reader by the
# extension): an input error naming the file, not an internal error.
bad_xml = os.path.join(args.workdir, "malformed.xml")
with open(bad_xml, "w") as f:
    f.write("<bad")
r = execute([bad_xml])
check(r.returncode == 1 and "cannot read '%s'" % bad_xml in r.stderr
      and "internal error" not in r.stderr,
      "malformed XML file: exit %d (1), message: %s" % (r.returncode, r.stderr.strip()[:160]))

# A plate neither supported by its edges nor in contact: the first Newton
# matrix is singular (a rigid motion is free). Before, the direct solvers
# returned a huge meaningless increment of zero energy and the run
# "converged" with w ~ 1e14. It must stop as a convergence failure (exit 2).
singular = os.path.join(args.workdir, "singular.prm")
with open(singular, "w") as f:
    f.write("set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 4, 4\n"
            "  set Boundary conditions = all: free\nend\n"
            "subsection Output\n  set Directory = %s\n  set Format = none\nend\n"
            % os.path.join(args.workdir, "singular-out"))
r = execute([singular])
check(r.returncode == 2 and "singular" in r.stderr and "not held by its edge conditions" in r.stderr
      and "internal error" not in r.stderr,
      "unsupported Kirchhoff plate: exit %d (2), message: %s" % (r.returncode, r.stderr.strip()[:200]))

# A tolerance below the round-off floor: once the contact status has
# settled, a frictionless Newton step is exact up to round-off, so the
# corrections stop decreasing (~5e-15 here). The driver must say so within
# a few iterations, not run to 'Maximum iterations' (100) and report a
# plain non-convergence; with 'Allow non-convergence' the run goes on.
here = os.path.dirname(os.path.abspath(__file__))
paper = open(os.path.join(here, "..", "..", "parameters", "paper_kirchhoff.prm")).read()
for allow in (False, True):
    tight = os.path.join(args.workdir, "tight%d.prm" % allow)
    with open(tight, "w") as f:
        f.write(paper + "\nsubsection Geometry\n  set Number of cycles = 1\nend\n"
                "subsection Nonlinear solver\n  set Tolerance = 1e-16\n"
                "  set Allow non-convergence = %s\nend\n"
                "subsection Output\n  set Directory = %s\n  set Format = none\nend\n"
                % ("true" if allow else "false", os.path.join(args.workdir, "tight%d-out" % allow)))
    r = execute([tight])
    iterations = [l for l in r.stdout.splitlines() if l.strip().startswith("iteration")]
    if not allow:
        check(r.returncode == 2 and "stagnated" in r.stderr and "round-off floor" in r.stderr
              and "Nonlinear solver/Tolerance" in r.stderr,
              "tolerance 1e-16: exit %d (2), message: %s" % (r.returncode, r.stderr.strip()[:160]))
    else:
        check(r.returncode == 0 and "NOT CONVERGED: the nonlinear solver stagnated" in r.stdout,
              "tolerance 1e-16 with 'Allow non-convergence': exit %d (0), reported as stagnated"
              % r.returncode)
    check(0 < len(iterations) < 40,
          "tolerance 1e-16: stopped after %d iterations (< 40 of the 100 allowed)" % len(iterations))

# Probe points and a profile line within round-off (1e-10 of the plate
# size) outside an edge are moved onto it: otherwise they pass
# the check and are then reported as NaN (null in summary.json).
edge = os.path.join(args.workdir, "edge.prm")
with open(edge, "w") as f:
    f.write("set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 4, 4\nend\n"
            "subsection Output\n  set Directory = %s\n  set Format = none\n"
            "  set Probe points = 10.0000000005, 5; -0.0000000005, 2.5\n"
            "  set Profile line = -0.0000000005, 5; 10.0000000005, 5\nend\n"
            % os.path.join(args.workdir, "edge-out"))
r = execute([edge])
summary = json.load(open(os.path.join(args.workdir, "edge-out", "summary.json")))
profile = open(os.path.join(args.workdir, "edge-out", "profile.csv")).read()
check(r.returncode == 0 and summary["cycles"][-1]["probes"] == [0, 0] and
      "nan" not in profile.lower(),
      "probe points and profile line 5e-10 outside the clamped edges: w = 0 "
      "there, no NaN (exit %d, probes %s)" % (r.returncode, summary["cycles"][-1]["probes"]))

# Input found invalid only on a refined mesh (an obstacle function that is
# not finite in a thin band, first met by the contact points of cycle 1):
# exit 1 naming the cycle, and the converged cycle 0 stays in summary.json.
# The same failure on cycle 0 with a nested new output directory removes
# what the run created, the parent included.
band = ("set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 16, 16\n"
        "  set Number of cycles = 2\nend\nsubsection Obstacle\n  set Type = function\n"
        "  set Height = -1 + 0*sqrt((x-5.0105)^2 - 1e-6)\nend\n")
late = os.path.join(args.workdir, "late.prm")
late_out = os.path.join(args.workdir, "late-out")
shutil.rmtree(late_out, ignore_errors=True)
with open(late, "w") as f:
    f.write(band + "subsection Output\n  set Directory = %s\n  set Format = none\nend\n" % late_out)
r = execute([late])
kept = os.path.join(late_out, "summary.json")
check(r.returncode == 1 and "Obstacle/Height" in r.stderr and "found on cycle 1" in r.stderr
      and os.path.exists(kept) and len(json.load(open(kept))["cycles"]) == 1,
      "obstacle not finite on cycle 1 only: exit %d (1), cycle named, cycle 0 kept: %s"
      % (r.returncode, r.stderr.strip()[-120:]))
nested_parent = os.path.join(args.workdir, "nested-parent")
shutil.rmtree(nested_parent, ignore_errors=True)
with open(late, "w") as f:
    f.write(band.replace("16, 16", "32, 32").replace("set Number of cycles = 2", "set Number of cycles = 1")
            + "subsection Output\n  set Directory = %s/child\n  set Format = none\nend\n"
            % nested_parent)
r = execute([late])
check(r.returncode == 1 and "Obstacle/Height" in r.stderr and not os.path.exists(nested_parent),
      "the same on cycle 0 with a new nested output directory: exit %d (1), nothing left"
      % r.returncode)

# Out of memory (a 3000 x 3000 Kirchhoff mesh under a 1 GB address-space
# limit): exit 3 with a message that says so and what to lower, and no
# output directory left behind (no cycle finished).
oom = os.path.join(args.workdir, "oom.prm")
oom_out = os.path.join(args.workdir, "oom-parent")
shutil.rmtree(oom_out, ignore_errors=True)
with open(oom, "w") as f:
    f.write("set Model = kirchhoff\nsubsection Geometry\n  set Subdivisions = 3000, 3000\n"
            "end\nsubsection Output\n  set Directory = %s/out\n  set Format = none\nend\n"
            % oom_out)
# (The mesh itself exceeds the limit, so the run fails while creating it,
# within a second. A limit reached inside OpenBLAS instead would make
# OpenBLAS wait for memory for ever, hence the timeout.)
try:
    r = subprocess.run([args.exe, oom], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True, cwd=args.workdir, timeout=120,
                       preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_AS,
                                                             (10**9, 10**9)))
except subprocess.TimeoutExpired:
    r = subprocess.CompletedProcess([], -1, "", "timed out after 120 s")
check(r.returncode == 3 and "out of memory" in r.stderr and "Geometry/Subdivisions" in r.stderr
      and not os.path.exists(oom_out),
      "out of memory on cycle 0: exit %d (3), message, nothing left: %s"
      % (r.returncode, r.stderr.strip()[-160:]))

r = execute([os.path.join(args.workdir, "does_not_exist.prm")])
check(r.returncode == 1 and "does_not_exist.prm" in r.stderr,
      "missing .prm: exit %d, message: %s" % (r.returncode, r.stderr.strip()))
r = execute([])
check(r.returncode == 1 and "no parameter file" in r.stderr,
      "no argument: exit %d, message: %s" % (r.returncode, r.stderr.strip().splitlines()[0]))
r = execute(["--frobnicate"])
check(r.returncode == 1 and "--frobnicate" in r.stderr,
      "unknown option: exit %d, message: %s" % (r.returncode, r.stderr.strip().splitlines()[0]))
r = execute(["--help"])
check(r.returncode == 0 and "Usage" in r.stdout, "--help: exit %d, prints usage" % r.returncode)
r = execute(["--print-parameters"])
check(r.returncode == 0 and "subsection Material" in r.stdout
      and "set Nitsche theta" in r.stdout,
      "--print-parameters: exit %d, prints the parameters" % r.returncode)
# what --print-parameters prints must itself be a valid parameter file
printed = os.path.join(args.workdir, "printed.prm")
with open(printed, "w") as f:
    f.write(r.stdout.replace("set Directory = results", "set Directory = %s"
                             % os.path.join(args.workdir, "printed-out")))
r2 = execute(["--help", printed])
check(r2.returncode == 0, "--help wins over a file argument")

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
