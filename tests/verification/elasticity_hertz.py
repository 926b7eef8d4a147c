"""Hertz contact: a rigid sphere pressed into an elastic block (3D model, Q2).

Set-up (quarter model): block [0,1]^2 x (-1/2, 1/2), E = 1, nu = 0.3, symmetry
on x = 0 and y = 0, the faces x = 1 and y = 1 free, the top face clamped; a
rigid sphere of radius R = 1 below the block, centre (0, 0, delta - R - 1/2),
i.e. its apex lies delta = 0.01 above the undeformed bottom face (initial
interpenetration delta). Frictionless, theta = 1, gamma0 = 20. The contact
region is resolved by 'Refinement box' (bottom corner cells, 1, 2, 3 extra
refinement steps: h = 1/8 -> 1/32 in-plane near the contact).

Independent reference: Hertz's solution for a rigid sphere on an elastic
half-space (e.g. K. L. Johnson, Contact Mechanics, ch. 4):
    a  = (3 P R / (4 E*))^(1/3),   p0 = 3 P / (2 pi a^2),   E* = E / (1 - nu^2),
evaluated with the total force the program computes, P = 4 * contact_force
(quarter model). The computed contact radius is a = sqrt(4 * area / pi) (the
area is a quarter disc), the computed peak pressure is
extra.max_contact_pressure (the Nitsche contact stress -Lambda_n at the
quadrature points, max at the centre).

Why these checks and tolerances:
- a(P) and p0(P) are local relations: comparing them at the computed P removes
  most of the finite-block effect, which is mainly a global compliance effect
  on the approach-force relation (here P is ~9 % above Hertz's
  P(delta) = 4/3 E* R^1/2 delta^3/2 for this bonded block of depth 1, so
  P(delta) is NOT checked). With a/t = a/L ~ 0.1 the remaining finite-size
  error is small but visible: a one-off run with 4 refinement steps (66k
  DoFs, 17 min with the reference BLAS) gives a -1.63 % and p0 +0.27 % off
  Hertz, versus -1.68 % and +0.57 % with 3 steps, i.e. a(P) converges to
  ~1.6 % below Hertz (a layer bonded to a rigid base is stiffer than the
  half-space, so its contact radius at a given load is smaller).
- Discretisation: the area counts contact quadrature points (5x5 Gauss per
  face), so its edge error is O(h/a) (~1/3 of a cell across a ~3 cells wide
  radius on the finest mesh); the peak pressure of Q2 near the kink of the
  pressure at the contact edge converges fast at the centre. Measured errors
  (1, 2, 3 steps): a: -12 %, -10 %, -1.7 %; p0: +75 %, +37 %, +0.6 %.
- Hence: on the finest mesh |a/a_H - 1| <= 3 % (1.6 % finite block + margin) and |p0/p0_H - 1| <= 3 %, and
  both errors must decrease from mesh to mesh (the coarse meshes are far off,
  so a wrong formulation, wrong Nitsche sign, wrong quarter-model boundary
  conditions or a wrong sphere gap cannot pass by luck). The approach-force
  relation is printed for information.
Runtime ~20 s in Release.
"""
import math
from common import parse_args, run, check, finish

args = parse_args()

E, NU, R, DELTA, T = 1.0, 0.3, 1.0, 0.01, 1.0
E_STAR = E / (1 - NU * NU)

TEMPLATE = """
set Model = elasticity
subsection Geometry
  set Length x = 1
  set Length y = 1
  set Thickness = %(t)r
  set Boundary conditions = 0: symmetry; 1: free; 2: symmetry; 3: free
  set Subdivisions = 4, 4, 8
  set Number of cycles = 1
end
subsection Material
  set Young's modulus = %(E)r
  set Poisson ratio = %(nu)r
end
subsection Load
  set Transverse load = 0
end
subsection Obstacle
  set Type = sphere
  set Sphere center = 0, 0, %(zc)r
  set Sphere radius = %(R)r
end
subsection Contact
  set Nitsche theta = 1
  set Nitsche gamma0 = 20
  set Friction coefficient = 0
end
subsection Elasticity
  set Polynomial degree = 2
  set Top face = clamped
  set Refinement box = 0, 0, -0.5; 0.2, 0.2, -0.4
  set Local refinement steps = %(steps)d
end
subsection Nonlinear solver
  set Tolerance = 1e-10
  set Maximum iterations = 50
end
subsection Output
  set Probe points = 0, 0
end
"""

errors_a, errors_p = [], []
for steps in (1, 2, 3):
    s, _ = run(args, "hertz_steps%d" % steps, TEMPLATE % dict(
        t=T, E=E, nu=NU, zc=DELTA - R - T / 2, R=R, steps=steps))
    c = s["cycles"][-1]
    check(c["converged"], "steps %d: %d DoFs, converged in %d iterations"
          % (steps, c["n_dofs"], c["nonlinear_iterations"]))
    P = 4 * c["contact_force"]
    a = math.sqrt(4 * c["contact_area"] / math.pi)
    p0 = c["extra"]["max_contact_pressure"]
    a_h = (3 * P * R / (4 * E_STAR)) ** (1.0 / 3.0)
    p0_h = 3 * P / (2 * math.pi * a_h ** 2)
    P_delta = 4.0 / 3.0 * E_STAR * math.sqrt(R) * DELTA ** 1.5
    ea, ep = a / a_h - 1, p0 / p0_h - 1
    errors_a.append(abs(ea))
    errors_p.append(abs(ep))
    print("      steps %d: P = %.6g (Hertz P(delta) = %.6g, ratio %.4f), "
          "a = %.5f vs Hertz %.5f (%+.2f %%), p0 = %.5f vs Hertz %.5f (%+.2f %%)"
          % (steps, P, P_delta, P / P_delta, a, a_h, 100 * ea, p0, p0_h, 100 * ep))
    # the apex of the contact zone is pushed up by delta (the sphere is rigid)
    check(abs(c["max_deflection"] - DELTA) <= 0.05 * DELTA,
          "steps %d: max u3 = %.5g == delta = %g within 5 %%"
          % (steps, c["max_deflection"], DELTA))

check(errors_a[-1] <= 0.03, "finest: contact radius error %.2f %% <= 3 %%" % (100 * errors_a[-1]))
check(errors_p[-1] <= 0.03, "finest: peak pressure error %.2f %% <= 3 %%" % (100 * errors_p[-1]))
check(errors_a[0] > errors_a[1] > errors_a[2],
      "contact radius error decreases: %s %%" % ", ".join("%.2f" % (100 * e) for e in errors_a))
check(errors_p[0] > errors_p[1] > errors_p[2],
      "peak pressure error decreases: %s %%" % ", ".join("%.2f" % (100 * e) for e in errors_p))
finish()
