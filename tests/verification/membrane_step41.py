"""deal.II's step-41 (the obstacle problem) moved to [0, 2]^2: T = 1, q = -10,
w = 0 on the boundary, Q1 on the 128 x 128 mesh (16,641 DoFs), the step
obstacle psi = -0.2, -0.4, -0.6, -0.8 on the four bands x < 0.5, < 1, < 1.5,
>= 1.5. With 'Contact quadrature rule = lobatto' and 2 points the contact
points are the mesh vertices, the nodes of step-41's active set. step-41's
published results (examples/step-41/doc/results.dox) end with 5399 nodes in
the active set after 18 active-set iterations. Checks the number of
vertices in contact, from scratch and by nested iteration from 16 x 16
(the same discrete problem: the same solution), and the deflection on the
steps. Prints the table of doc/membrane.md with the Newton iterations next
to step-41's."""
import csv, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, finish
from membrane_lib.membrane import membrane_prm

args = parse_args()
STEP41_ACTIVE_NODES, STEP41_ITERATIONS = 5399, 18
obstacle = ("set Type = function\n"
            "  set Height = x < 0.5 ? -0.2 : (x < 1 ? -0.4 : (x < 1.5 ? -0.6 : -0.8))")
probes = "0.25, 1; 0.75, 1; 1.25, 1; 1.75, 1"


def step41(name, refinement, cycles):
    s, _ = run(args, name,
               membrane_prm(lx=2, ly=2, sub=(1, 1), refinement=refinement, cycles=cycles,
                            load=-10, obstacle=obstacle, rule="lobatto", points=2,
                            alpha=0.01, probes=probes,
                            extra="subsection Output\n  set Contact points = true\nend\n"))
    vertices = []
    for c in s["cycles"]:
        check(c["converged"], "%s cycle %d: converged" % (name, c["cycle"]))
        path = os.path.join(args.workdir, name, "contact_points-%02d.csv" % c["cycle"])
        with open(path) as f:
            rows = list(csv.DictReader(f))
        # a vertex appears once per cell around it, with the same values
        vertices.append(len({(r["x"], r["y"]) for r in rows if int(r["status"]) != 0}))
    return s, vertices


scratch, v_scratch = step41("step41_scratch", 7, 1)
nested, v_nested = step41("step41_nested", 4, 4)
last, single = nested["cycles"][-1], scratch["cycles"][0]
check(last["n_dofs"] == single["n_dofs"] == 16641, "16641 DoFs as in step-41")
check(v_scratch[0] == STEP41_ACTIVE_NODES,
      "from U = 0: %d vertices in contact, step-41: %d" % (v_scratch[0], STEP41_ACTIVE_NODES))
check(v_nested[-1] == STEP41_ACTIVE_NODES,
      "nested: %d vertices in contact, step-41: %d" % (v_nested[-1], STEP41_ACTIVE_NODES))
# the same discrete problem solved twice: the same solution
diff = max(abs(a - b) for a, b in zip(single["probes"], last["probes"]))
check(diff <= 1e-9, "nested and from-scratch solutions agree at the probes (%.1e)" % diff)
# the membrane rests on the three upper steps at the probes
for w, psi in zip(last["probes"][:3], (-0.2, -0.4, -0.6)):
    check(abs(w - psi) <= 1e-4, "w = %.6f on the step psi = %g" % (w, psi))

print("\n| mesh | DoFs | vertices in contact | Newton iterations (nested) | contact force |")
print("|---|---|---|---|---|")
for c, v in zip(nested["cycles"], v_nested):
    n = 16 * 2 ** c["cycle"]
    print("| %d x %d | %d | %d | %d | %.5f |" % (n, n, c["n_dofs"], v, c["nonlinear_iterations"],
                                               c["contact_force"]))
print("| 128 x 128 from U = 0 | %d | %d | %d | %.5f |" % (single["n_dofs"], v_scratch[0],
                                                       single["nonlinear_iterations"],
                                                       single["contact_force"]))
print("| step-41, 128 x 128 | 16641 | %d | %d active-set iterations | |"
      % (STEP41_ACTIVE_NODES, STEP41_ITERATIONS))
finish()
