#!/usr/bin/env bash
# The test command: install what is missing, build in Release, run every
# test (unit, whole-program regression, verification, input errors).
cd "$(dirname "$0")/.."
source tests/setup.sh
cd build
ctest -j"$jobs" --output-on-failure --timeout 1500
