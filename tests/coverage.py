#!/usr/bin/env python3
"""Line coverage of the project's sources after a test run of a build
configured by tests/coverage.sh (gcc --coverage). Merges the counts of every
translation unit (headers included), prints covered / executable lines per
file and, with --uncovered, the lines never executed, grouped in runs.

  python3 tests/coverage.py BUILD_DIR SOURCE_DIR [--uncovered]

Uses gcov's JSON output (gcc >= 9); standard library only."""
import argparse
import collections
import glob
import gzip
import json
import os
import subprocess
import tempfile

ap = argparse.ArgumentParser()
ap.add_argument("build")
ap.add_argument("source")
ap.add_argument("--uncovered", action="store_true")
args = ap.parse_args()
source = os.path.realpath(args.source)
counts = collections.defaultdict(lambda: collections.defaultdict(int))
with tempfile.TemporaryDirectory() as work:
    for gcda in glob.glob(os.path.join(args.build, "CMakeFiles", "**", "*.gcda"),
                          recursive=True):
        subprocess.run(["gcov", "-j", "-o", gcda, gcda], cwd=work, capture_output=True)
        for j in glob.glob(os.path.join(work, "*.gcov.json.gz")):
            for f in json.load(gzip.open(j))["files"]:
                name = os.path.realpath(f["file"])
                if name.startswith(source + os.sep):
                    for line in f["lines"]:
                        counts[name][line["line_number"]] += line["count"]
            os.remove(j)
if not counts:
    raise SystemExit("no coverage data under %s (build with tests/coverage.sh, "
                     "then run ctest there)" % args.build)
total = covered = 0
for name in sorted(counts):
    lines = counts[name]
    hit = sum(1 for v in lines.values() if v > 0)
    total, covered = total + len(lines), covered + hit
    print("%5d / %5d  %5.1f %%  %s" % (hit, len(lines), 100. * hit / len(lines),
                                      os.path.relpath(name, source)))
    if args.uncovered:
        text = open(name).read().split("\n")
        previous = -2
        for n in sorted(l for l, v in lines.items() if v == 0):
            if n != previous + 1:
                print("        --")
            print("        %5d  %s" % (n, text[n - 1].rstrip()[:100]))
            previous = n
print("%5d / %5d  %5.1f %%  all" % (covered, total, 100. * covered / total))
