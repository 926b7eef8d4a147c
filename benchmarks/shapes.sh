#!/bin/bash
# Benchmark of the Mindlin plate (MITC4, direct solver, the program's
# defaults) on every shape with about the same number of DoFs: the paper's
# plate (t = 0.01, E = 2e5, q = -0.02, the plane z = -1 below, clamped
# outside, holes free), nested over four cycles. One row per shape: the
# finest cycle's DoFs and Newton iterations, the wall-clock seconds per
# phase summed over the cycles, and the run's wall clock and peak memory.
# The rectangle, the L-shape and the rectangle with hole share one element
# data per cycle; the disk, the annulus and the mesh file compute it per
# cell (doc/mindlin.md). Usage:
#   benchmarks/shapes.sh [path/to/nitsche-contact] [refinements]
# The second argument adds global refinements to every shape (default 0:
# about 150,000 DoFs on the finest cycle; 1: about 600,000).
# The program must be built with CMAKE_BUILD_TYPE=Release.
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
exe=${1:-$here/build/nitsche-contact}
extra=${2:-0}
case "$extra" in
  ''|*[!0-9]*) echo "benchmarks/shapes.sh: refinements must be an integer >= 0, not '$extra'" >&2; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shape entries and the initial refinement that gives about 28^2 cells on
# the first cycle
shapes=(
  "rectangle|set Shape = rectangle|0"
  "L-shape|set Shape = L-shape\n  set Subdivisions = 32, 32|0"
  "rectangle with hole|set Shape = rectangle with hole\n  set Hole size = 2.5, 2.5\n  set Subdivisions = 32, 32\n  set Boundary conditions = 4: free; all: clamped|0"
  "disk|set Shape = disk|3"
  "annulus|set Shape = annulus\n  set Inner radius = 2\n  set Boundary conditions = 0: clamped; 1: free|3"
  "mesh file|set Shape = mesh file\n  set Mesh file = $here/parameters/meshes/plate_with_hole.msh\n  set Boundary conditions = 1: clamped; 2: free|1"
)
printf '%-20s %9s %4s %8s %9s %8s %9s %8s %9s\n' shape dofs its setup assembly solve postproc wall "peak MB"
for entry in "${shapes[@]}"; do
  IFS='|' read -r name geometry refinement <<< "$entry"
  tag=${name// /_}
  printf 'set Model = mindlin\nsubsection Geometry\n  set Subdivisions = 28, 28\n  %b\n  set Initial refinement = %d\n  set Number of cycles = 4\nend\nsubsection Output\n  set Directory = %s\n  set Format = none\nend\n' \
    "$geometry" $((refinement + extra)) "$work/$tag" > "$work/$tag.prm"
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
