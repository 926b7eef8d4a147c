#!/usr/bin/env python3
"""Adaptive against uniform refinement, in one invocation: the membrane (Q2)
and the Mindlin plate (MITC9, 'gsv') on an L-shaped plate (re-entrant
corner) and on the paper's test, each on uniform cycles, on adaptive cycles
(Bulk fraction 0.3) and on a reference run two uniform refinements finer
than the finest uniform cycle. The reference reaction is the Aitken
extrapolation of the reference run's last three cycles when their
increments contract (at the re-entrant corner the uniform reaction converges
too slowly for its finest cycle to serve), else that run's finest cycle;
the error of a cycle is its reaction's relative distance from it
(the error estimate is printed beside it). Per case: every cycle's DoFs,
relative estimate, reaction error, Newton iterations and the cumulative
wall time (the phases of summary.json summed over the cycles), and the DoFs
and the time from which on the adaptive run stays at or below the finest
uniform run's error. With a second argument, the
plot of error and estimate against DoFs (matplotlib) goes to that PNG.
Usage:
  benchmarks/adaptive.py [path/to/nitsche-contact] [plot.png]
The program must be built with CMAKE_BUILD_TYPE=Release. The 3D model has
no estimator yet and is not part of this benchmark."""
import json, os, shutil, subprocess, sys, tempfile

here = os.path.dirname(os.path.abspath(__file__))
exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "build", "nitsche-contact")
plot = sys.argv[2] if len(sys.argv) > 2 else None
if not os.access(exe, os.X_OK):
    sys.exit("benchmarks/adaptive.py: no executable program at '%s'" % exe)

MEMBRANE = """set Model = membrane
subsection Geometry
  set Length x = 2
  set Length y = 2
  %s
end
subsection Load
  set Transverse load = -10
end
subsection Obstacle
  set Level = -0.15
end
subsection Membrane
  set Element degree = 2
end
"""
MINDLIN = """set Model = mindlin
subsection Geometry
  %s
end
subsection Mindlin
  set Shear treatment = MITC9
end
subsection Nonlinear solver
  set Tolerance = 1e-8
  set Maximum iterations = 400
end
"""
# (name, text, shape entries, uniform cycles, adaptive cycles)
CASES = [
    ("membrane, L-shape", MEMBRANE, "set Shape = L-shape\n  set Subdivisions = 4, 4", 6, 32),
    ("membrane, paper's test shape", MEMBRANE, "set Subdivisions = 4, 4", 6, 32),
    ("Mindlin MITC9, L-shape", MINDLIN, "set Shape = L-shape\n  set Subdivisions = 4, 4", 5, 30),
    ("Mindlin MITC9, paper's test", MINDLIN, "set Subdivisions = 4, 4", 5, 30),
]


def run(work, name, text, graphical=False):
    out = os.path.join(work, name)
    prm = out + ".prm"
    with open(prm, "w") as f:
        f.write(text + "subsection Contact\n  set Obstacle compliance = 0\nend\n"
                "subsection Output\n  set Directory = %s\n  set Format = %s\nend\n"
                % (out, "vtu" if graphical else "none"))
    proc = subprocess.run([exe, prm], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if proc.returncode != 0:
        sys.exit("%s failed (status %d):\n%s" % (name, proc.returncode, proc.stdout[-2000:]))
    with open(os.path.join(out, "summary.json")) as f:
        cycles = json.load(f)["cycles"]
    if graphical:
        cycles[-1]["cells"] = last_mesh(out, len(cycles) - 1)
    elapsed = 0.
    for c in cycles:
        elapsed += sum(c["wall_times"].values())
        c["cumulative_seconds"] = elapsed
    return cycles


def last_mesh(directory, cycle):
    """[(corner x's, corner y's, eta_K)] of the cells of a cycle's VTU file
    (deal.II's patches of the Q2 and MITC9 cases: 3 x 3 points per cell,
    lexicographic, cell data repeated at each)."""
    sys.path.insert(0, os.path.join(here, "..", "tests", "verification"))
    from common import read_vtu
    import glob
    arrays = read_vtu(glob.glob(os.path.join(directory, "*_%02d.0.vtu" % cycle))[0])
    points, eta = arrays["Points"][0], arrays["error_indicator"][0]
    cells = []
    side = 3
    n = side * side
    for c in range(len(eta) // n):
        corners = [c * n, c * n + side - 1, c * n + n - 1, c * n + n - side]
        cells.append(([points[3 * k] for k in corners], [points[3 * k + 1] for k in corners],
                      eta[c * n]))
    return cells


def geometry(shape, refinement, cycles):
    return "%s\n  set Refinement = %s\n  set Number of cycles = %d" % (shape, refinement, cycles)


work = tempfile.mkdtemp()
results = []
try:
    for name, text, shape, n_uniform, n_adaptive in CASES:
        tag = name.split(",")[0].split()[0].lower() + ("_l" if "L-shape" in name else "_paper")
        uniform = run(work, tag + "_uniform", text % geometry(shape, "global", n_uniform))
        fine = run(work, tag + "_reference", text % geometry(shape, "global", n_uniform + 2))
        adaptive = run(work, tag + "_adaptive", text % geometry(shape, "adaptive", n_adaptive),
                       graphical=plot is not None)
        f0, f1, f2 = (c["contact_force"] for c in fine[-3:])
        contracting = abs(f2 - f1) < abs(f1 - f0)
        ref = f2 - (f2 - f1) ** 2 / ((f2 - f1) - (f1 - f0)) if contracting else f2
        reference = dict(fine[-1], contact_force=ref, extrapolated=contracting,
                         last_three=(f0, f1, f2))
        for c in uniform + adaptive:
            c["error"] = abs(c["contact_force"] - ref) / ref
        results.append((name, uniform, adaptive, reference))
finally:
    shutil.rmtree(work, ignore_errors=True)

for name, uniform, adaptive, reference in results:
    print("\n%s (reference: %s %d DoFs, reaction %.8f)"
          % (name, "extrapolated from up to" if reference["extrapolated"] else
             "the uniform run's increments do not contract: its cycle of",
             reference["n_dofs"], reference["contact_force"]))
    f0, f1, f2 = reference["last_three"]
    print("  its last three reactions %.8f, %.8f, %.8f (relative increments %.2e, %.2e)"
          % (f0, f1, f2, (f1 - f0) / f1, (f2 - f1) / f2))
    print("%-9s %5s %8s %11s %11s %6s %9s" % ("run", "cycle", "DoFs", "eta/|U|_a",
                                             "reaction e", "its", "seconds"))
    for label, cycles in (("uniform", uniform), ("adaptive", adaptive)):
        for c in cycles:
            print("%-9s %5d %8d %11.3e %11.3e %6d %9.2f"
                  % (label, c["cycle"], c["n_dofs"], c["error_estimate_relative"], c["error"],
                     c["nonlinear_iterations"], c["cumulative_seconds"]))
    finest = uniform[-1]
    below = [all(d["error"] <= finest["error"] for d in adaptive[k:])
             for k in range(len(adaptive))]
    reached = [c for c, b in zip(adaptive, below) if b]
    if reached:
        a = reached[0]
        print("finest uniform error %.2e (%d DoFs, %.2f s): the adaptive run stays below it "
              "from cycle %d on: %d DoFs (%.3f of them), %.2f s (%.3f)"
              % (finest["error"], finest["n_dofs"], finest["cumulative_seconds"], a["cycle"],
                 a["n_dofs"], a["n_dofs"] / finest["n_dofs"], a["cumulative_seconds"],
                 a["cumulative_seconds"] / finest["cumulative_seconds"]))
    else:
        print("finest uniform error %.2e: the adaptive run ends above it (%.2e at %d DoFs)"
              % (finest["error"], adaptive[-1]["error"], adaptive[-1]["n_dofs"]))

if plot:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("benchmarks/adaptive.py: the plot needs the Python package matplotlib")
    fig, axes = plt.subplots(1, len(results), figsize=(4.2 * len(results), 3.8))
    for ax, (name, uniform, adaptive, _) in zip(axes, results):
        for label, cycles, colour in (("uniform", uniform, "tab:blue"),
                                      ("adaptive", adaptive, "tab:red")):
            n = [c["n_dofs"] for c in cycles]
            ax.loglog(n, [max(c["error"], 1e-12) for c in cycles], "o-", ms=3, color=colour,
                      label=label + ": reaction error")
            ax.loglog(n, [c["error_estimate_relative"] for c in cycles], "s--", ms=2,
                      color=colour, alpha=0.6, label=label + ": eta/|U|_a")
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("DoFs")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(plot, dpi=110)
    # the last adapted meshes, each cell coloured by its indicator
    import math
    from matplotlib.collections import PolyCollection
    fig, axes = plt.subplots(1, len(results), figsize=(4.2 * len(results), 4.0))
    for ax, (name, _, adaptive, _) in zip(axes, results):
        cells = adaptive[-1]["cells"]
        polygons = [list(zip(x, y)) for x, y, _ in cells]
        colours = [math.log10(max(e, 1e-300)) for _, _, e in cells]
        collection = PolyCollection(polygons, array=colours, cmap="viridis",
                                    edgecolors="k", linewidths=0.15)
        ax.add_collection(collection)
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_title("%s: cycle %d, %d DoFs" % (name, adaptive[-1]["cycle"],
                                                 adaptive[-1]["n_dofs"]), fontsize=8)
        fig.colorbar(collection, ax=ax, shrink=0.7, label="log10 eta_K")
    fig.tight_layout()
    meshes = plot[:-4] + "_meshes.png" if plot.endswith(".png") else plot + "_meshes.png"
    fig.savefig(meshes, dpi=110)
    print("\nplots: %s, %s" % (plot, meshes))
