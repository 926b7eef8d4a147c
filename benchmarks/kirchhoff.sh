#!/bin/sh
# Benchmark of the Kirchhoff model on the paper's test (parameters/
# paper_kirchhoff.prm): nested iteration over N cycles starting from 16x16
# cells, GSV theta = 1. Prints DoFs, Newton and Krylov iterations and
# seconds per phase per cycle, the total wall time and the peak memory.
#   usage: benchmarks/kirchhoff.sh [BUILD_DIR] [CYCLES] [SOLVER] [TOLERANCE] [OBSTACLE] [STOP]
# SOLVER is 'multigrid' (default: CG + geometric multigrid, linear in the
# number of dofs) or 'direct' (MUMPS; uses BLAS, so an optimised BLAS such
# as OpenBLAS speeds it up). TOLERANCE is the Newton tolerance (default
# 1e-9: at 1M dofs 1e-10 of the .prm is at the round-off floor). OBSTACLE
# is 'gsv' (default: GSV alpha*D = 1e-4 with 'Contact/Obstacle compliance =
# auto'), 'rigid' (GSV with the compliance 0) or 'penalty' (alpha = 0,
# kappa = 1e-6: the pure penalty / elastic obstacle of compliance 1e-6,
# doc/kirchhoff.md). STOP is 'Nonlinear solver/Active-set stop' (default
# true).
# 6 cycles = 512x512 cells = 1,052,676 dofs (with 'multigrid' about 1.1 GB,
# doc/benchmarks.md has the time; with 'direct' about 2.2 GB and minutes);
# 7 cycles = 1024x1024 cells = 4,202,500 dofs (multigrid, about 3.9 GB;
# its round-off floor is near 1e-9, so give TOLERANCE 1e-8 there).
# Build in Release first.
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
cycles=${2:-6}
solver=${3:-multigrid}
tol=${4:-1e-9}
obstacle=${5:-gsv}
stop=${6:-true}
case "$stop" in
  true|false) ;;
  *) echo "benchmarks/kirchhoff.sh: STOP must be 'true' or 'false', not '$stop'" >&2; exit 1 ;;
esac
case "$obstacle" in
  gsv) alpha=1e-4; kappa=auto ;;
  rigid) alpha=1e-4; kappa=0 ;;
  penalty) alpha=0; kappa=1e-6 ;;
  *) echo "benchmarks/kirchhoff.sh: OBSTACLE must be 'gsv', 'rigid' or 'penalty', not '$obstacle'" >&2; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the paper's file with this run's entries after it (a later 'set' wins)
{ cat "$here/parameters/paper_kirchhoff.prm"
  cat <<EOF
subsection Geometry
  set Number of cycles = $cycles
end
subsection Contact
  set Obstacle compliance = $kappa
end
subsection Kirchhoff
  set Stabilisation alpha = $alpha
  subsection Linear solver
    set Type = $solver
  end
end
subsection Nonlinear solver
  set Tolerance          = $tol
  set Maximum iterations = 100
  set Print iterations   = false
  set Active-set stop    = $stop
end
subsection Output
  set Directory     = $work/out
  set Format        = none
  set Print timings = true
end
EOF
} > "$work/bench.prm"
/usr/bin/time -v "$build/nitsche-contact" "$work/bench.prm" > "$work/log" 2> "$work/time" ||
  { cat "$work/log" "$work/time"; exit 1; }
python3 - "$work/out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
p = s["parameters"]
print("Kirchhoff, paper test; alpha*D = %s, kappa = %s; linear solver: %s" % (p.get("alpha*D"), p.get("obstacle compliance kappa"), p.get("linear solver", "direct " + p.get("direct solver", ""))))
print("%5s %9s %4s %7s %7s %8s %8s %8s %9s" % ("cycle", "dofs", "its", "krylov", "setup",
      "assembly", "solve", "total", "force"))
acc = 0.0
for c in s["cycles"]:
    t = c["wall_times"]
    tot = sum(t.values())
    acc += tot
    print("%5d %9d %4d %7d %7.2f %8.2f %8.2f %8.2f %9.6f" % (c["cycle"], c["n_dofs"],
          c["nonlinear_iterations"], c.get("linear_iterations", 0), t["setup"], t["assembly"],
          t["solve"], tot, c["contact_force"]))
print("sum of phases over all cycles: %.1f s" % acc)
PY
grep -E "Elapsed|Maximum resident" "$work/time"
