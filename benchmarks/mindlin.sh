#!/bin/bash
# Benchmark of the Mindlin model on the paper's test (parameters/
# paper_mindlin.prm): DoFs, nonlinear iterations and wall-clock seconds per
# phase for each refinement cycle, in Release. Usage:
#   benchmarks/mindlin.sh [path/to/nitsche-contact] [number of cycles] [lobatto|gauss]
#                         [direct|multigrid] [subdivisions] [mitc4|mitc9] [kappa]
#                         [nitsche|gsv]
# The third argument selects the contact points: 'lobatto' (default, as the
# program without friction: 2x2 Gauss-Lobatto = the cell vertices) or
# 'gauss' (4x4 Gauss points; doc/mindlin.md). The fourth the linear
# solver: 'direct' (default, MUMPS) or 'multigrid' (CG with the V-cycle over
# Kirchhoff coarse levels, doc/mindlin.md). The fifth the subdivisions
# of the first mesh per direction (default 8, as the .prm; 10 with 7 cycles
# gives 640^2 cells = 1,232,643 dofs). The sixth the element: 'mitc4'
# (default, paper_mindlin.prm) or 'mitc9' (parameters/paper_mindlin_mitc9.prm,
# biquadratic; 'lobatto' is then 3x3 Gauss-Lobatto = the Q2 nodes, the
# default subdivisions 4, the same nodes as MITC4 on 8; direct solver only).
# The seventh the obstacle's compliance 'Contact/Obstacle compliance'
# (default 0: rigid; 'auto': the program's default, doc/formulations.md;
# 1e-5: an elastic obstacle whose penalty length the 640^2 mesh resolves,
# doc/mindlin.md). The eighth 'Mindlin/Contact formulation' (default
# nitsche, the paper's form as in the .prm; gsv the plate's equilibrium
# stress, doc/mindlin.md).
# The program must be built with CMAKE_BUILD_TYPE=Release.
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$here/build/nitsche-contact}
cycles=${2:-7}
rule=${3:-lobatto}
solver=${4:-direct}
element=${6:-mitc4}
kappa=${7:-0}
formulation=${8:-nitsche}
case "$formulation" in
  nitsche|gsv) ;;
  *) echo "benchmarks/mindlin.sh: contact formulation must be 'nitsche' or 'gsv', not '$formulation'" >&2; exit 1 ;;
esac
case "$kappa" in
  auto) ;;
  ''|*[!0-9.eE+-]*) echo "benchmarks/mindlin.sh: kappa must be 'auto' or a number >= 0, not '$kappa'" >&2; exit 1 ;;
esac
case "$element" in
  mitc4) prm=paper_mindlin.prm; subdivisions=${5:-8}; vertex_points=2 ;;
  mitc9) prm=paper_mindlin_mitc9.prm; subdivisions=${5:-4}; vertex_points=3 ;;
  *) echo "benchmarks/mindlin.sh: element must be 'mitc4' or 'mitc9', not '$element'" >&2; exit 1 ;;
esac
case "$solver" in
  direct|multigrid) ;;
  *) echo "benchmarks/mindlin.sh: solver must be 'direct' or 'multigrid', not '$solver'" >&2; exit 1 ;;
esac
case "$subdivisions" in
  ''|*[!0-9]*) echo "benchmarks/mindlin.sh: subdivisions must be a positive integer, not '$subdivisions'" >&2; exit 1 ;;
esac
case "$rule" in
  gauss) points=4 ;;
  lobatto) points=$vertex_points ;;
  *) echo "benchmarks/mindlin.sh: contact rule must be 'gauss' or 'lobatto', not '$rule'" >&2; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the paper's file with this run's entries after it (a later 'set' wins)
{ cat "$here/parameters/$prm"
  cat <<EOF
subsection Geometry
  set Number of cycles = $cycles
  set Subdivisions     = $subdivisions, $subdivisions
end
subsection Contact
  set Obstacle compliance = $kappa
end
subsection Mindlin
  set Contact formulation       = $formulation
  set Contact quadrature points = $points
  set Contact quadrature rule   = $rule
  subsection Linear solver
    set Type = $solver
  end
end
subsection Nonlinear solver
  set Print iterations = false
end
subsection Output
  set Directory = $work/out
  set Format    = none
end
EOF
} > "$work/bench.prm"
start=$(date +%s.%N)
if [ -x /usr/bin/time ]; then
  /usr/bin/time -v "$exe" "$work/bench.prm" > "$work/log" 2> "$work/time" ||
    { cat "$work/log" "$work/time"; exit 1; }
else
  "$exe" "$work/bench.prm" > "$work/log" || { cat "$work/log"; exit 1; }
fi
end=$(date +%s.%N)
python3 - "$work/out/summary.json" "$start" "$end" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print("Mindlin model, paper test (clamped [0,10]^2, t = 0.01, q = -0.02, obstacle -1)")
print("linear solver: %s" % s["parameters"].get("linear solver", "?"))
print("contact formulation: %s" % s["parameters"].get("contact formulation", "?"))
print("obstacle compliance kappa: %s" % s["parameters"].get("obstacle compliance kappa", "0 (rigid)"))
print("%5s %9s %5s %7s %8s %8s %8s %8s %8s %9s %10s" % ("cycle", "dofs", "its", "krylov",
      "setup", "assembly", "solve", "postproc", "total", "force", "w(1,5)"))
acc = 0.0
for c in s["cycles"]:
    t = c["wall_times"]
    tot = t["setup"] + t["assembly"] + t["solve"] + t["postprocess"] + t["output"]
    acc += tot
    print("%5d %9d %5d %7d %8.2f %8.2f %8.2f %8.2f %8.2f %9.6f %10.6f" % (c["cycle"],
          c["n_dofs"], c["nonlinear_iterations"], c.get("linear_iterations", 0),
          t["setup"], t["assembly"], t["solve"],
          t["postprocess"], tot, c["contact_force"], c["probes"][2]))
print("sum of phases %.1f s, wall clock of the run %.1f s"
      % (acc, float(sys.argv[3]) - float(sys.argv[2])))
PY
[ -f "$work/time" ] && grep -E "Maximum resident" "$work/time"
exit 0
