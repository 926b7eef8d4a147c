#!/bin/bash
# Benchmark of one model on every shape it solves, with about the same
# number of DoFs per shape: the paper's plate (t = 0.01, E = 2e5,
# q = -0.02, the plane z = -1 below, clamped outside, holes free), nested
# over four cycles, the program's defaults. One row per shape: the finest
# cycle's DoFs and Newton iterations, the wall-clock seconds per phase
# summed over the cycles, and the run's wall clock and peak memory.
# mindlin (MITC4, direct solver): every shape, to about 150,000 DoFs; the
# rectangle, the L-shape and the rectangle with hole share one element data
# per cycle, the disk, the annulus and the mesh file compute it per cell
# (doc/mindlin.md). kirchhoff: the Cartesian shapes from 16^2 to 128^2
# cells. elasticity: every shape, one Q2 layer, the Cartesian ones from 8^2
# to 64^2 cells in plane, the others refined in plane over as many cycles
# as give about 100,000 DoFs. Usage:
#   benchmarks/shapes.sh [path/to/nitsche-contact] [refinements] [model]
# The second argument adds global refinements to every shape (default 0;
# 1 gives about four times the DoFs), the third is the model (default
# mindlin). The program must be built with CMAKE_BUILD_TYPE=Release.
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$here/build/nitsche-contact}
extra=${2:-0}
model=${3:-mindlin}
case "$extra" in
  ''|*[!0-9]*) echo "benchmarks/shapes.sh: refinements must be an integer >= 0, not '$extra'" >&2; exit 1 ;;
esac
hole="set Shape = rectangle with hole\n  set Hole size = 2.5, 2.5\n  set Boundary conditions = 4: free; all: clamped"
case "$model" in
  mindlin) subdivisions="28, 28"; settings="" ;;
  kirchhoff) subdivisions="16, 16"; settings="" ;;
  elasticity) subdivisions="8, 8, 1"
              settings="subsection Elasticity\n  set Refine through thickness = false\nend" ;;
  *) echo "benchmarks/shapes.sh: the model must be mindlin, kirchhoff or elasticity, not '$model'" >&2; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shape entries, the initial refinement (Mindlin: about 28^2 cells on the
# first cycle) and the number of cycles
if [ "$model" = mindlin ]; then
  shapes=(
    "rectangle|set Shape = rectangle|0"
    "L-shape|set Shape = L-shape\n  set Subdivisions = 32, 32|0"
    "rectangle with hole|$hole\n  set Subdivisions = 32, 32|0"
    "disk|set Shape = disk|3"
    "annulus|set Shape = annulus\n  set Inner radius = 2\n  set Boundary conditions = 0: clamped; 1: free|3"
    "mesh file|set Shape = mesh file\n  set Mesh file = $here/parameters/meshes/plate_with_hole.msh\n  set Boundary conditions = 1: clamped; 2: free|1"
  )
elif [ "$model" = elasticity ]; then
  shapes=(
    "rectangle|set Shape = rectangle|0"
    "L-shape|set Shape = L-shape|0"
    "rectangle with hole|$hole|0"
    "disk|set Shape = disk|0|5"
    "annulus|set Shape = annulus\n  set Inner radius = 2\n  set Boundary conditions = 0: clamped; 1: free|0|5"
    "mesh file|set Shape = mesh file\n  set Mesh file = $here/parameters/meshes/plate_with_hole.msh\n  set Boundary conditions = 1: clamped; 2: free|0|3"
  )
else
  shapes=(
    "rectangle|set Shape = rectangle|0"
    "L-shape|set Shape = L-shape|0"
    "rectangle with hole|$hole|0"
  )
fi
printf '%-20s %9s %4s %8s %9s %8s %9s %8s %9s\n' shape dofs its setup assembly solve postproc wall "peak MB"
for entry in "${shapes[@]}"; do
  IFS='|' read -r name geometry refinement cycles <<< "$entry"
  tag=${name// /_}
  printf 'set Model = %s\nsubsection Geometry\n  set Subdivisions = %s\n  %b\n  set Initial refinement = %d\n  set Number of cycles = %d\nend\n%b\nsubsection Output\n  set Directory = %s\n  set Format = none\nend\n' \
    "$model" "$subdivisions" "$geometry" $((refinement + extra)) "${cycles:-4}" "$settings" "$work/$tag" > "$work/$tag.prm"
  start=$(date +%s.%N)
  /usr/bin/time -f '%M' -o "$work/$tag.mem" "$exe" "$work/$tag.prm" > "$work/$tag.log" 2>&1 ||
    { echo "benchmarks/shapes.sh: $name failed:"; tail -20 "$work/$tag.log"; exit 1; }
  end=$(date +%s.%N)
  python3 - "$work/$tag/summary.json" "$name" "$start" "$end" "$(cat "$work/$tag.mem")" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
last = s["cycles"][-1]
phase = lambda key: sum(c["wall_times"][key] for c in s["cycles"])
print("%-20s %9d %4d %8.2f %9.2f %8.2f %9.2f %8.1f %9.0f" % (
    sys.argv[2], last["n_dofs"], last["nonlinear_iterations"], phase("setup"),
    phase("assembly"), phase("solve"), phase("postprocess"),
    float(sys.argv[4]) - float(sys.argv[3]), int(sys.argv[5]) / 1024))
PY
done
