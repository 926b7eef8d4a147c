"""The exact line search's fast path ('Nonlinear solver/Fast line search',
doc/design.md) against the assembled residual (the option set to false),
the independent second method: phi'(t) = R(U + t dU).dU from point values
along the step must equal the slope of the residual assembled at U + t dU.
 - 3D elasticity, the paper's test (Q2, 8 x 8 x 1 then 16 x 16 x 1),
   Gauss-Lobatto contact points with gamma0 = 60 (coercive,
   nitsche_trace_constant), on 1 rank with and without the fast path and on
   2 ranks with it (its sums over the ranks);
 - Kirchhoff GSV, the paper's test from 16^2 to 32^2 cells, with its
   uniform load and with a load varying in x (the fast path's other branch:
   the load at the quadrature points instead of one constant);
 - 3D elasticity, block on a sphere with local refinement (hanging nodes),
   on 1 and 2 ranks.
Checks: the first line-search step of the cold start (of cycle 1 for the
sphere; an exact line search from the same iterate in every run: the same
phi' gives the same secant iterates) is the same to the 4 printed
decimals, and so is every log line of that cycle up to it; per cycle both runs converge, the contact force and the probe
deflections agree to 1e-5 (3D, Newton tolerance 1e-6) or 1e-8 (Kirchhoff),
the active sets to 0.5 % (compare_cycle)."""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import shipped_prm, parse_args, run, check, compare_cycle, finish

args = parse_args()
here = os.path.dirname(os.path.abspath(__file__))


def prm_from(name, replacements, fast):
    return shipped_prm(name, replacements,
                       "\nsubsection Nonlinear solver\n  set Fast line search = %s\n"
                       "  set Print iterations = true\nend\n" % ("true" if fast else "false"))


def iteration_lines(out, cycle):
    """The iteration lines of a cycle, up to and including the first one
    with a line-search step < 1, and that step."""
    lines = []
    first = re.split(r"(?m)^Cycle \d+:", out)[1 + cycle]
    for line in first.splitlines():
        if re.match(r"\s*iteration\s+\d+:", line):
            lines.append(line.strip())
            m = re.search(r"step (\d\.\d+)$", line)
            if m:
                return lines, m.group(1)
    return lines, None


elasticity_changes = [("Number of cycles", "2"), ("Subdivisions", "8, 8, 1"),
                      ("Tolerance", "1e-6"),
                      ("Refine through thickness", "false\n  set Contact quadrature rule = lobatto"),
                      ("Nitsche gamma0", "60")]
kirchhoff_changes = [("Number of cycles", "2")]
varying_load = kirchhoff_changes + [("Transverse load", "-0.02 * (1 + 0.5 * sin(x / 3))")]
# hanging nodes (local refinement) in the 3D model; cycle 1 starts with a
# line search (the constrained rows must not enter phi')
sphere_changes = [("Line search", "true\n  set Nonmonotone window = 0")]
sphere = os.path.join(here, "..", "runs", "elasticity_sphere.prm")

cases = [("elasticity", "paper_3d.prm", elasticity_changes, 1e-5, [1, 2], 0),
         ("kirchhoff", "paper_kirchhoff.prm", kirchhoff_changes, 1e-8, [1], 0),
         ("kirchhoff_varying_load", "paper_kirchhoff.prm", varying_load, 1e-8, [1], 0),
         ("sphere", sphere, sphere_changes, 1e-8, [1, 2], 1)]

for tag, prm, changes, rtol, ranks, cycle in cases:
    ref, out_ref = run(args, tag + "_assembled", prm_from(prm, changes, False))
    lines_ref, step_ref = iteration_lines(out_ref, cycle)
    check(step_ref is not None,
          "%s: cycle %d takes a line-search step (iteration %d, step %s)"
          % (tag, cycle, len(lines_ref), step_ref))
    for np in ranks:
        name = "%s_fast_np%d" % (tag, np)
        new, out_new = run(args, name, prm_from(prm, changes, True), np=np)
        lines_new, step_new = iteration_lines(out_new, cycle)
        check(lines_new == lines_ref,
              "%s: the iterations of cycle %d up to its first line-search "
              "step are the same (step %s, assembled %s)"
              % (name, cycle, step_new, step_ref))
        for k, (cr, cn) in enumerate(zip(ref["cycles"], new["cycles"])):
            compare_cycle("%s cycle %d" % (name, k), cr, cn, rtol,
                          ("assembled", "fast"))
finish()
