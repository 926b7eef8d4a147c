#!/usr/bin/env python3
"""The current speed of every model on its largest benchmark case, with the
program's defaults, in one table and one plot:

  /usr/bin/python3 benchmarks/current.py [build/nitsche-contact] [results/benchmarks]

Cases (the paper's test unless said otherwise, graphical output off):
  kirchhoff   paper_kirchhoff.prm over 6 cycles, 16^2 -> 512^2 (1,052,676 DoFs),
              multigrid, Newton tolerance 1e-9
  mindlin     paper_mindlin_large.prm, 10^2 -> 640^2 (1,232,643 DoFs), multigrid,
              on its elastic obstacle of compliance 1e-5
  3d          paper_3d_large.prm, 88^2 x 1 Q2 cells (281,961 DoFs), two-level
              solver, 2 MPI ranks
  membrane    membrane.prm (step-41's problem), 16^2 -> 128^2 (16,641 DoFs)
Writes OUT/benchmarks.md (the machine, the date, the commit, and per case
and cycle the DoFs, Newton iterations and seconds of summary.json; the wall
time of the whole run) and OUT/benchmarks.png (seconds per cycle against
its DoFs). doc/benchmarks.md quotes the table."""
import datetime
import json
import os
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..")
exe = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "nitsche-contact"))
out = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else "results/benchmarks")
os.makedirs(out, exist_ok=True)

CASES = [
    ("kirchhoff", "paper_kirchhoff.prm", 1,
     "subsection Geometry\n  set Number of cycles = 6\nend\n"
     "subsection Nonlinear solver\n  set Tolerance = 1e-9\nend\n"
     "subsection Kirchhoff\n  subsection Linear solver\n    set Type = multigrid\n  end\nend\n"),
    ("mindlin", "paper_mindlin_large.prm", 1, ""),
    ("3d", "paper_3d_large.prm", 2, ""),
    ("membrane", "membrane.prm", 1, ""),
]


def machine():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                            text=True).stdout.strip() or "unknown"
    return cpu, os.cpu_count(), datetime.date.today().isoformat(), commit


def run(name, prm, ranks, extra):
    outdir = os.path.join(out, name)
    text = open(os.path.join(root, "parameters", prm)).read() + "\n" + extra + \
        "subsection Output\n  set Directory = %s\n  set Format = none\nend\n" % outdir
    prm_out = os.path.join(out, name + ".prm")
    with open(prm_out, "w") as f:
        f.write(text)
    cmd = [exe, prm_out]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    print("== %s: %s" % (name, " ".join(cmd)), flush=True)
    t0 = time.time()
    with open(os.path.join(out, name + ".log"), "w") as log:
        status = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, env=env).returncode
    wall = time.time() - t0
    if status != 0:
        print("   failed (exit %d), see %s.log" % (status, outdir), flush=True)
        return None
    cycles = json.load(open(os.path.join(outdir, "summary.json")))["cycles"]
    print("   %d DoFs, %.1f s" % (cycles[-1]["n_dofs"], wall), flush=True)
    return dict(name=name, prm=prm, ranks=ranks, wall=wall, cycles=cycles)


def write(results):
    cpu, cores, date, commit = machine()
    lines = ["Measured by `benchmarks/current.py` on %s (%d cores), %s, commit %s."
             % (cpu, cores, date, commit), "",
             "| case | ranks | cycle | DoFs | Newton its | seconds (phases) | wall of the run [s] |",
             "|---|---|---|---|---|---|---|"]
    for r in results:
        for c in r["cycles"]:
            seconds = sum(c["wall_times"].values()) if isinstance(c.get("wall_times"), dict) else float("nan")
            last = c is r["cycles"][-1]
            lines.append("| %s | %d | %d | %d | %d | %.2f | %s |" % (
                r["name"], r["ranks"], c["cycle"], c["n_dofs"], c["nonlinear_iterations"],
                seconds, "%.1f" % r["wall"] if last else ""))
    with open(os.path.join(out, "benchmarks.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib not available: no benchmarks.png")
        return
    fig, ax = plt.subplots(figsize=(7, 4))
    for r in results:
        pts = [(c["n_dofs"], sum(c["wall_times"].values())) for c in r["cycles"]
               if isinstance(c.get("wall_times"), dict)]
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=r["name"])
    ax.set_xlabel("DoFs of the cycle")
    ax.set_ylabel("seconds of the cycle")
    ax.set_title("%s, %d cores, %s, %s" % (cpu, cores, date, commit), fontsize=8)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "benchmarks.png"), dpi=120)


results = [r for r in (run(*case) for case in CASES) if r]
write(results)
sys.exit(0 if len(results) == len(CASES) else 1)
