#!/bin/bash
# Debug build with line coverage, the whole test suite on it, and the
# coverage per source file (tests/coverage.py). Not part of CI: the Debug
# build links deal.II's debug library, whose assertions (index bounds,
# vector sizes, ...) check the program too, and runs the suite about 5
# times slower (about an hour on 2 cores; verification/nonmonotone_newton
# exceeds its 1200 s limit there). Usage:
#   bash tests/coverage.sh [--uncovered] [build directory, default build-coverage]
# (--uncovered also lists the lines that never ran)
set -e
here=$(cd "$(dirname "$0")/.." && pwd)
flags=()
if [ "${1:-}" = "--uncovered" ]; then
  flags=(--uncovered)
  shift
fi
build=$(realpath -m "${1:-$here/build-coverage}")
# (the packages are those tests/setup.sh installs; run tests/run_tests.sh once first)
mkdir -p "$build"
cd "$build"
find . -name '*.gcda' -delete
cmake -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS=--coverage \
      -DCMAKE_EXE_LINKER_FLAGS=--coverage "$here" > cmake.log
make -j2 > make.log
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
ctest -j2 --timeout 3600 > ctest.log 2>&1 || echo "some tests failed: see $build/ctest.log"
PY=python3; [ -x /usr/bin/python3 ] && PY=/usr/bin/python3
"$PY" "$here/tests/coverage.py" "$build" "$here" "${flags[@]}"
