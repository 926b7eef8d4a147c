#!/bin/bash
# 'Contact/Obstacle compliance = auto' (the default) against the rigid
# obstacle (0) on the large cases of the paper's test, one run after the
# other on this machine:
#   kirchhoff   parameters/paper_kirchhoff.prm over 6 cycles (16^2 -> 512^2,
#               1,052,676 DoFs), multigrid, Newton tolerance 1e-9
#   mindlin     parameters/paper_mindlin_large.prm (1,232,643 DoFs)
#   3d          parameters/paper_3d_large.prm on 2 MPI ranks (281,961 DoFs)
#   membrane    parameters/membrane.prm (step-41's obstacle) over 7 cycles
#               (16^2 -> 1024^2 Q1 cells, 1,050,625 DoFs)
# Prints two markdown tables. The runs: Newton iterations per cycle,
# wall-clock seconds (/usr/bin/time), the reaction, the probe deflections
# and the compliance's penetration of the last cycle. The effect: per case
# and quantity, auto - rigid on the last cycle against the rigid run's
# change from the cycle before (none for a run of one cycle).
#   usage: benchmarks/compliance.sh [BUILD_DIR] [CASES]
# CASES is a list like "kirchhoff mindlin 3d membrane" (the default). Build
# in Release first.
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
cases=${2:-"kirchhoff mindlin 3d membrane"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| case | compliance | kappa | Newton iterations per cycle | wall [s] | reaction | probes | penetration |"
echo "|---|---|---|---|---|---|---|---|"
for case in $cases; do
  case "$case" in
    kirchhoff)
      prm="$here/parameters/paper_kirchhoff.prm"; launch=""
      extra="subsection Geometry\n  set Number of cycles = 6\nend\nsubsection Nonlinear solver\n  set Tolerance = 1e-9\nend\nsubsection Kirchhoff\n  subsection Linear solver\n    set Type = multigrid\n  end\nend" ;;
    mindlin) prm="$here/parameters/paper_mindlin_large.prm"; launch=""; extra="" ;;
    3d) prm="$here/parameters/paper_3d_large.prm"; launch="mpirun -np 2"; extra="" ;;
    membrane)
      prm="$here/parameters/membrane.prm"; launch=""
      extra="subsection Geometry\n  set Number of cycles = 7\nend\nsubsection Output\n  set Contact points = false\nend" ;;
    *) echo "benchmarks/compliance.sh: unknown case '$case' (kirchhoff, mindlin, 3d, membrane)" >&2; exit 1 ;;
  esac
  for compliance in 0 auto; do
    out="$work/$case-$compliance"
    { cat "$prm"; printf "\n$extra\n"
      printf 'subsection Contact\n  set Obstacle compliance = %s\nend\n' "$compliance"
      printf 'subsection Output\n  set Directory = %s\n  set Format = none\nend\n' "$out"; } > "$out.prm"
    /usr/bin/time -f "%e" -o "$out.time" $launch "$build/nitsche-contact" "$out.prm" > "$out.log" 2>&1 ||
      { tail -20 "$out.log"; exit 1; }
    python3 - "$out/summary.json" "$out.time" "$case" "$compliance" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))["cycles"]
wall = float(open(sys.argv[2]).read().split()[-1])
print("| %s | %s | %.3g | %s | %.1f | %.7f | %s | %.2g |" % (
    sys.argv[3], sys.argv[4], c[-1]["obstacle_compliance"],
    ", ".join(str(x["nonlinear_iterations"]) for x in c), wall, c[-1]["contact_force"],
    ", ".join("%.7f" % w for w in c[-1]["probes"]), c[-1]["compliance_penetration"]))
PY
  done
done
# the layer's effect on the last cycle (auto - rigid) against the rigid
# run's change from the cycle before, per quantity
echo
echo "| case | quantity | effect: auto - rigid | rigid: last change | ratio |"
echo "|---|---|---|---|---|"
for case in $cases; do
  python3 - "$work/$case-0/summary.json" "$work/$case-auto/summary.json" "$case" <<'PY'
import json, sys
summary = json.load(open(sys.argv[1]))
rigid = summary["cycles"]
auto = json.load(open(sys.argv[2]))["cycles"]
names = ["reaction"] + ["w(%g, %g)" % tuple(p) for p in summary["probe_points"]]
values = lambda c: [c["contact_force"]] + c["probes"]
for i, name in enumerate(names):
    effect = abs(values(auto[-1])[i] - values(rigid[-1])[i])
    if len(rigid) > 1:
        change = abs(values(rigid[-1])[i] - values(rigid[-2])[i])
        print("| %s | %s | %.2g | %.2g | %.2g |" % (sys.argv[3], name, effect, change,
                                                  effect / change) if change > 0 else
              "| %s | %s | %.2g | 0 | — |" % (sys.argv[3], name, effect))
    else:
        print("| %s | %s | %.2g | — | — |" % (sys.argv[3], name, effect))
PY
done
