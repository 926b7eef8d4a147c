#!/usr/bin/env bash
# The main job: install what is missing, build in Release, and run the
# paper's test with every model (results/comparison/).
cd "$(dirname "$0")/.."
source tests/setup.sh
PY=python3; [ -x /usr/bin/python3 ] && PY=/usr/bin/python3
"$PY" parameters/compare_models.py --exe build/nitsche-contact --out results/comparison "$@"
