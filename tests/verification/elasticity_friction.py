"""Coulomb friction of the 3D model: stick/slip threshold of a pressed block
under a tangential load.

Set-up: block [0,2] x [0,1] x (-0.1, 0.1) (flat, so that the shear load
cannot tip it: tipping needs s t > p L / 2, i.e. s > 10 p), E = 100,
nu = 0.3, on a rigid plane at its bottom face (gap 0), top traction
(s, 0, -p) with p = 1, friction coefficient F = 0.5. The faces x = 0 and
x = 2 are free; the faces y = 0 and y = 1 have symmetry conditions (u2 = 0),
which remove the y translation and the rotation about z but leave the
x translation restrained only by friction.

Exact facts (independent of the mesh, theta and gamma0):
- global equilibrium: v = e1 and v = e3 are discrete test functions with
  zero strain and zero sigma(v), so the discrete equations give exactly
  (up to the solver tolerance)
      total normal reaction      P = integral of -Lambda_n = p * A,
      total tangential reaction  T = -integral of Lambda_t,x = s * A,
  with A = 2 the contact area;
- the Coulomb law |Lambda_t| <= -F Lambda_n holds pointwise (ball
  projection), with equality at sliding points;
- hence |T| <= F P: for s > F p NO discrete solution exists, the program
  must report failure (exit status 2) instead of a "converged" result;
  for s < F p a solution exists (a sticking core holds the block).
Checked: s / (F p) = 0.5 (everything sticks here; fixed point = Newton,
since the fixed point then assembles the same linear system), 0.9 for
theta = 1, 0, -1 (Q1) and theta = 1 (Q2), and 0.98 (partial slip: both stick
and slip points, max |Lambda_t| / |Lambda_n| = F): converged, P = p A and
T = s A to 1e-8 relative, max ratio <= F; s / (F p) = 1.02 and 1.2: exit
status 2. Measured (Q1, theta = 1): 0.5 all 512 contact points stick;
0.9: 336 stick / 176 slip; 0.98: 48 stick / 464 slip.
The paper's fixed point with partial slip is printed for information: it
freezes the slip direction and threshold (Tresca-like), so it carries no
tangential stiffness at sliding points and, here, does not converge or
meets a singular frozen system (exit status 2) once slip occurs.
The partial-slip runs with theta = 1 and Q1 also write the contact-face
VTU: its face means 'tangential_stress' (|Lambda_t|) and
'contact_pressure' obey the Coulomb law face by face (mean |Lambda_t| <=
F mean |Lambda_n|), integrate to p A and to the summary's
tangential_force, which lies in [s A, F p A] (float32: 1e-5).
Runtime ~15 s in Release.
"""
import os
import re
from common import (parse_args, run, check, finish, sliding_block_prm, read_vtu,
                    integrate_patch_field)

args = parse_args()

P, F, AREA = 1.0, 0.5, 2.0

def prm(ratio, theta=1, degree=1, scheme="newton", maxit=60):
    return sliding_block_prm(sub="8, 4, 2" if degree == 1 else "4, 2, 1",
                             q=-P, theta=theta, F=F, degree=degree,
                             s=ratio * F * P, scheme=scheme, maxit=maxit)


def name(ratio, theta=1, degree=1, scheme="newton"):
    return "friction_%g_theta%d_Q%d_%s" % (ratio, theta, degree,
                                            scheme.replace(" ", "_"))


def check_equilibrium(c, ratio, tag, slip_expected):
    s = ratio * F * P
    ex = c["extra"]
    check(c["converged"], tag + " converged in %d iterations" % c["nonlinear_iterations"])
    check(abs(c["contact_force"] - P * AREA) <= 1e-8 * P * AREA,
          tag + " normal reaction %.12g == p A = %g" % (c["contact_force"], P * AREA))
    # the obstacle's tangential force on the block balances the top shear
    check(abs(ex["tangential_resultant_x"] + s * AREA) <= 1e-8 * s * AREA,
          tag + " tangential reaction %.12g == -s A = %.12g"
          % (ex["tangential_resultant_x"], -s * AREA))
    check(abs(ex["tangential_resultant_y"]) <= 1e-10,
          tag + " tangential reaction y %.3g == 0" % ex["tangential_resultant_y"])
    # |integral of Lambda_t| <= integral of |Lambda_t| <= F x normal force
    check(s * AREA * (1 - 1e-8) <= ex["tangential_force"] <= F * P * AREA * (1 + 1e-9),
          tag + " s A = %.12g <= integral of |Lambda_t| %.12g <= F p A = %.12g"
          % (s * AREA, ex["tangential_force"], F * P * AREA))
    check(ex["max_friction_ratio"] <= 1 + 1e-9,
          tag + " max |Lambda_t|/(F |Lambda_n|) = %.12g <= 1" % ex["max_friction_ratio"])
    print("      %s stick %d, slip %d of %d contact points"
          % (tag, c["stick_points"], c["slip_points"], c["contact_points"]))
    if slip_expected:
        check(c["slip_points"] > 0 and c["stick_points"] > 0,
              tag + " partial slip (stick %d, slip %d)" % (c["stick_points"], c["slip_points"]))
        check(abs(ex["max_friction_ratio"] - 1) <= 1e-9,
              tag + " the Coulomb bound is reached at slip points (%.12g == 1)"
              % ex["max_friction_ratio"])
    else:
        check(c["slip_points"] == 0 and c["stick_points"] == c["contact_points"],
              tag + " everything sticks (%d of %d)" % (c["stick_points"], c["contact_points"]))


# well below the threshold: full stick; fixed point and Newton coincide
newton, _ = run(args, name(0.5), prm(0.5))
check_equilibrium(newton["cycles"][-1], 0.5, "s/(Fp)=0.5 newton:", False)
fixed, _ = run(args, name(0.5, scheme="fixed point"), prm(0.5, scheme="fixed point"))
check_equilibrium(fixed["cycles"][-1], 0.5, "s/(Fp)=0.5 fixed point:", False)
a, b = newton["cycles"][-1]["probes"][0], fixed["cycles"][-1]["probes"][0]
check(abs(a - b) <= 1e-9 * abs(a),
      "s/(Fp)=0.5: fixed point = Newton (mid-plane u3 %.12g vs %.12g)" % (b, a))



def check_vtu(ratio, tag):
    """The contact-face VTU of the last run: its face means of |Lambda_t|
    ('tangential_stress') and of -Lambda_n ('contact_pressure') obey the
    Coulomb law face by face (a mean of |Lambda_t| <= F |Lambda_n| is at
    most F times the mean of |Lambda_n|), and their integrals are
    bracketed by the equilibrium values: s A <= integral |Lambda_t| <= F p A
    and integral of the pressure = p A (float32 output: 1e-5)."""
    s = ratio * F * P
    directory = os.path.join(args.workdir, name(ratio))
    pieces = [read_vtu(os.path.join(directory, f)) for f in sorted(os.listdir(directory))
              if re.match(r"contact-\d+\.\d+\.vtu$", f)]
    check(len(pieces) == 1, tag + " one contact-face VTU piece (%d)" % len(pieces))
    if not pieces:
        return
    tangential = sum(integrate_patch_field(a, "tangential_stress")[0] for a in pieces)
    pressure = sum(integrate_patch_field(a, "contact_pressure")[0] for a in pieces)
    check(abs(pressure - P * AREA) <= 1e-5 * P * AREA,
          tag + " VTU contact_pressure integrates to p A: %.7g" % pressure)
    check(s * AREA * (1 - 1e-5) <= tangential <= F * P * AREA * (1 + 1e-5),
          tag + " s A = %g <= VTU integral of tangential_stress %.7g <= F p A = %g"
          % (s * AREA, tangential, F * P * AREA))
    worst = max(t - F * p for a in pieces
                for t, p in zip(a["tangential_stress"][0], a["contact_pressure"][0]))
    check(worst <= 1e-5 * F * P,
          tag + " VTU tangential_stress <= F contact_pressure on every face "
          "(largest excess %.3g)" % worst)
    return tangential


# partial slip, all theta, and close to the threshold
for ratio, theta, degree in ((0.9, 1, 1), (0.9, 0, 1), (0.9, -1, 1), (0.9, 1, 2),
                             (0.98, 1, 1)):
    vtu = (theta, degree) == (1, 1)
    s, _ = run(args, name(ratio, theta, degree), prm(ratio, theta, degree),
               output_format="vtu" if vtu else "none")
    tag = "s/(Fp)=%g theta=%+d Q%d:" % (ratio, theta, degree)
    check_equilibrium(s["cycles"][-1], ratio, tag, True)
    if vtu:
        tangential = check_vtu(ratio, tag)
        if tangential is not None:
            ex = s["cycles"][-1]["extra"]
            check(abs(tangential - ex["tangential_force"]) <= 1e-5 * ex["tangential_force"],
                  tag + " VTU integral of tangential_stress %.7g == summary "
                  "tangential_force %.7g" % (tangential, ex["tangential_force"]))

# above the threshold: no equilibrium exists
for ratio in (1.02, 1.2):
    _, out = run(args, name(ratio), prm(ratio), expect_status=2)
    msg = [l for l in out.splitlines() if "error" in l]
    check(len(msg) == 1, "s/(Fp)=%g: exit status 2 with one message: %s"
          % (ratio, msg[0] if msg else "(none)"))

# information: the paper's fixed point with partial slip
import subprocess
import os
os.makedirs(args.workdir, exist_ok=True)
path = os.path.join(args.workdir, "friction_0.9_fixed_point.prm")
with open(path, "w") as f:
    f.write(prm(0.9, scheme="fixed point", maxit=60))
    f.write("\nsubsection Output\n  set Directory = %s\n  set Format = none\nend\n"
            % os.path.join(args.workdir, "friction_0.9_fixed_point"))
proc = subprocess.run([args.exe, path], stdout=subprocess.PIPE,
                      stderr=subprocess.STDOUT, text=True)
print("      info: fixed point, s/(Fp)=0.9: exit status %d (%s)"
      % (proc.returncode, (proc.stdout.strip().splitlines() or [""])[-1][:160]))
finish()
