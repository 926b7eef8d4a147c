#!/bin/sh
# Benchmark of the Kirchhoff model on the paper's test (parameters/
# paper_kirchhoff.prm): nested iteration over N cycles starting from 16x16
# cells, GSV theta = 1. Prints DoFs, iterations and seconds per phase per
# cycle, the total wall time and the peak memory.
#   usage: benchmarks/kirchhoff.sh [BUILD_DIR] [CYCLES]
# Build in Release first. Set LD_LIBRARY_PATH to an optimised BLAS (e.g.
# OpenBLAS) to speed up MUMPS: the Debian default is the reference BLAS.
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
cycles=${2:-5}
work=$(mktemp -d)
sed -e "s/set Number of cycles = .*/set Number of cycles = $cycles/" \
    -e "s#set Directory = .*#set Directory = $work/out#" \
    -e "s/set Format = vtu/set Format = none/" \
    -e "s/set Maximum iterations = 100/set Maximum iterations = 100\n  set Print iterations = false/" \
    -e "s/set Format = none/set Format = none\n  set Print timings = true/" \
    "$here/parameters/paper_kirchhoff.prm" > "$work/bench.prm"
/usr/bin/time -v "$build/nitsche-contact" "$work/bench.prm" > "$work/log" 2> "$work/time"
sed -n '/^cycle dofs/,/^$/p' "$work/log" | cut -c1-40
sed -n '/Wall-clock seconds per phase/,$p' "$work/log"
grep -E "Elapsed|Maximum resident" "$work/time"
rm -rf "$work"
