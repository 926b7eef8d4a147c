#!/bin/sh
# Times two versions of the program side by side on the three large cases:
#   3d         parameters/paper_3d_large.prm (282,000 DoFs, two-level
#              solver, plate predictor) on 2 MPI ranks
#   kirchhoff  benchmarks/kirchhoff.sh's default (the paper's test, 6 cycles
#              to 1,052,676 DoFs, multigrid)
#   mindlin    parameters/paper_mindlin_large.prm (1,232,643 DoFs,
#              multigrid)
# Each version runs its own shipped parameter files (entry names may differ
# between versions), graphical output off. The runs alternate between the
# versions, REPEATS times each; the script prints every run's wall time and
# peak memory, then per case the medians and the ratio new/old.
#   usage: benchmarks/compare_versions.sh OLD_CHECKOUT NEW_CHECKOUT [REPEATS] [CASES]
# Each checkout needs a Release build in its build/ directory. CASES is a
# list like "3d kirchhoff mindlin" (the default).
set -e
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
repeats=${3:-3}
cases=${4:-"3d kirchhoff mindlin"}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run VERSION_DIR CASE TAG: one timed run; appends "case tag seconds MB"
run() {
  dir=$1; case_name=$2; tag=$3
  out="$work/$tag-$case_name"
  rm -rf "$out"
  case "$case_name" in
    3d)
      { cat "$dir/parameters/paper_3d_large.prm"
        printf 'subsection Output\n  set Directory = %s\n  set Format = none\nend\n' "$out"
      } > "$work/$tag.prm"
      /usr/bin/time -v mpirun -np 2 "$dir/build/nitsche-contact" "$work/$tag.prm" \
        > "$work/log" 2> "$work/time" || { tail "$work/log" "$work/time"; exit 1; } ;;
    mindlin)
      { cat "$dir/parameters/paper_mindlin_large.prm"
        printf 'subsection Output\n  set Directory = %s\n  set Format = none\nend\n' "$out"
      } > "$work/$tag.prm"
      /usr/bin/time -v "$dir/build/nitsche-contact" "$work/$tag.prm" \
        > "$work/log" 2> "$work/time" || { tail "$work/log" "$work/time"; exit 1; } ;;
    kirchhoff)
      "$dir/benchmarks/kirchhoff.sh" "$dir/build" > "$work/log" 2>&1 ||
        { tail "$work/log"; exit 1; }
      cp "$work/log" "$work/time" ;;
    *) echo "benchmarks/compare_versions.sh: unknown case '$case_name'" >&2; exit 1 ;;
  esac
  python3 - "$work/time" "$case_name" "$tag" >> "$work/table" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text)
parts = [float(x) for x in m.group(1).split(":")]
seconds = sum(p * 60 ** (len(parts) - 1 - i) for i, p in enumerate(parts))
kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1))
print(sys.argv[2], sys.argv[3], "%.2f" % seconds, "%.0f" % (kb / 1024.))
PY
  tail -n 1 "$work/table"
}

for case_name in $cases; do
  i=0
  while [ $i -lt "$repeats" ]; do
    run "$old" "$case_name" old
    run "$new" "$case_name" new
    i=$((i + 1))
  done
done

python3 - "$work/table" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print("\n%-10s %10s %10s %8s %9s %9s" % ("case", "old [s]", "new [s]", "new/old", "old [MB]", "new [MB]"))
for case in dict.fromkeys(r[0] for r in rows):
    t = {v: [float(r[2]) for r in rows if r[0] == case and r[1] == v] for v in ("old", "new")}
    m = {v: [float(r[3]) for r in rows if r[0] == case and r[1] == v] for v in ("old", "new")}
    mo, mn = statistics.median(t["old"]), statistics.median(t["new"])
    print("%-10s %10.2f %10.2f %8.3f %9.0f %9.0f" % (case, mo, mn, mn / mo,
          max(m["old"]), max(m["new"])))
PY
