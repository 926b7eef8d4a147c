#!/bin/bash
# Benchmark of the 3D elasticity model on the paper's test (parameters/
# paper_3d.prm: clamped [0,10]^2 x (-0.005,0.005), Q2, body force -0.02/t,
# plane obstacle x3 = -1, theta = 1, frictionless), starting
# from a coarse 8x8x1 mesh (nested iteration). Each cycle doubles the
# in-plane subdivisions and keeps one Q2 layer through the thickness
# ('plane', as paper_3d.prm) or refines every cell in all three directions
# ('all': the layers double too). Prints DoFs, nonlinear iterations and
# wall-clock seconds per phase (from summary.json, 'Print timings = true'),
# and the peak memory of the largest process (one MPI rank) when
# /usr/bin/time is installed.
# The sixth argument selects the 3x3 contact points per face: 'lobatto'
# (default, as the program: the Q2 face nodes) or 'gauss'. The seventh sets
# gamma0 (default 60, the program's 'auto' for the 3D model; with the
# Lobatto points theta = 1 needs gamma0 above their trace constant 33.6 on
# these flat cells, doc/formulations.md). The eighth sets the in-plane
# subdivisions of the first mesh (default 8; 11 with 4 cycles gives
# 88x88x1 cells, 281,961 DoFs). The table's column 'neg' is the largest
# number of negative eigenvalues of a Newton matrix of the cycle (from the
# L D L^T factorisation; '-' when it was LU or the two-level solver), 'lin'
# the linear iterations of the cycle (GMRES; 1 per reused factorisation
# with 'direct'). The ninth selects how MUMPS factorises the (symmetric,
# theta = 1) Newton matrices: 'ldlt' (default) or 'lu' (through Amesos).
# The tenth selects how each cycle starts: 'auto' (default, as the
# program: the plate where it applies), 'plate' ('Elasticity/Plate
# predictor = true': the Mindlin plate's solution lifted to 3D; the column
# 'pred' then gives its Newton iterations, whose seconds are part of
# 'setup') or 'nested' (the previous cycle's solution, U = 0 on the first).
# The third argument selects the linear solver: 'direct' (MUMPS), 'two-level'
# (GMRES with the column smoother and the plate coarse space; Krylov
# tolerance 1e-8, doc/benchmarks.md) or 'amg'.
# Usage:
#   benchmarks/elasticity.sh [path/to/nitsche-contact] [cycles] [direct|amg|two-level] [ranks] [plane|all] [lobatto|gauss] [gamma0] [subdivisions] [ldlt|lu] [auto|nested|plate]
# The program must be built with CMAKE_BUILD_TYPE=Release. Nonlinear
# tolerance 1e-6 (the round-off floor of this thin plate is ~1e-7).
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$here/build/nitsche-contact}
cycles=${2:-2}
solver=${3:-direct}
case "$solver" in
  direct|amg) krylov=1e-10 ;;
  two-level) krylov=1e-8 ;;
  *) echo "benchmarks/elasticity.sh: solver must be 'direct', 'amg' or 'two-level', not '$solver'" >&2; exit 1 ;;
esac
ranks=${4:-1}
case "${5:-plane}" in
  plane) through=false ;;
  all) through=true ;;
  *) echo "benchmarks/elasticity.sh: refinement must be 'plane' or 'all', not '$5'" >&2; exit 1 ;;
esac
rule=${6:-lobatto}
case "$rule" in
  gauss|lobatto) ;;
  *) echo "benchmarks/elasticity.sh: contact rule must be 'gauss' or 'lobatto', not '$rule'" >&2; exit 1 ;;
esac
gamma0=${7:-60}
case "$gamma0" in
  ''|*[!0-9.e+-]*) echo "benchmarks/elasticity.sh: gamma0 must be a positive number, not '$gamma0'" >&2; exit 1 ;;
esac
factorization=${9:-ldlt}
case "$factorization" in
  ldlt) symmetric=true ;;
  lu) symmetric=false ;;
  *) echo "benchmarks/elasticity.sh: factorization must be 'ldlt' or 'lu', not '$factorization'" >&2; exit 1 ;;
esac
case "${10:-auto}" in
  auto) predictor=auto ;;
  nested) predictor=false ;;
  plate) predictor=true ;;
  *) echo "benchmarks/elasticity.sh: start must be 'auto', 'nested' or 'plate', not '${10}'" >&2; exit 1 ;;
esac
subdivisions=${8:-8}
case "$subdivisions" in
  ''|*[!0-9]*|0) echo "benchmarks/elasticity.sh: subdivisions must be a positive integer, not '$subdivisions'" >&2; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the paper's file with this run's entries after it (a later 'set' wins)
{ cat "$here/parameters/paper_3d.prm"
  cat <<EOF
subsection Geometry
  set Number of cycles = $cycles
  set Subdivisions     = $subdivisions, $subdivisions, 1
end
subsection Contact
  set Nitsche gamma0 = $gamma0
end
subsection Elasticity
  set Refine through thickness = $through
  set Contact quadrature rule  = $rule
  set Plate predictor          = $predictor
  subsection Linear solver
    set Type                    = $solver
    set Krylov tolerance        = $krylov
    set Symmetric factorization = $symmetric
  end
end
subsection Output
  set Directory     = $work/out
  set Format        = none
  set Print timings = true
end
EOF
} > "$work/bench.prm"
run=("$exe")
if [ "$ranks" -gt 1 ]; then run=(mpirun -np "$ranks" "$exe"); fi
start=$(date +%s.%N)
# /usr/bin/time (Debian package 'time') reports the peak resident memory of
# the largest process (one MPI rank); without it the line is left out
timer=()
if [ -x /usr/bin/time ]; then timer=(/usr/bin/time -v -o "$work/time"); fi
"${timer[@]}" "${run[@]}" "$work/bench.prm" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
end=$(date +%s.%N)
python3 - "$work/out/summary.json" "$start" "$end" "$solver" "$ranks" "$rule" "$gamma0" "$factorization" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print("3D elasticity model (Q2), paper test, linear solver %s (%s), %s MPI rank(s), "
      "3x3 %s contact points per face, gamma0 %s (trace constant C_n %.3g)"
      % (sys.argv[4], sys.argv[8], sys.argv[5], sys.argv[6], sys.argv[7],
         dict(s["cycles"][-1]["extra"])["nitsche_trace_constant"]))
print("%5s %9s %5s %5s %6s %8s %8s %8s %8s %8s %8s %9s %5s" % ("cycle", "dofs", "its", "pred", "lin",
      "setup", "assembly", "solve", "postproc", "output", "total", "force", "neg"))
acc = 0.0
for c in s["cycles"]:
    t = c["wall_times"]
    tot = t["setup"] + t["assembly"] + t["solve"] + t["postprocess"] + t["output"]
    acc += tot
    neg = dict(c["extra"]).get("newton_negative_eigenvalues")
    print("%5d %9d %5d %5s %6d %8.2f %8.2f %8.2f %8.2f %8.2f %8.2f %9.6f %5s" % (c["cycle"], c["n_dofs"],
          c["nonlinear_iterations"], c.get("predictor_iterations", "-"),
          c.get("linear_iterations", 0),
          t["setup"], t["assembly"], t["solve"],
          t["postprocess"], t["output"], tot, c["contact_force"],
          "-" if neg is None else "%d" % neg))
print("sum of phases %.1f s, wall clock of the run %.1f s"
      % (acc, float(sys.argv[3]) - float(sys.argv[2])))
PY
if [ -f "$work/time" ]; then
  awk -F': ' '/Maximum resident/ {printf "peak memory of the largest process %.2f GB\n", $2 / 1048576}' "$work/time"
fi
