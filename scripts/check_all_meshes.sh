#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the CLI on every mesh of ../shared/data (up to MAX_FACES faces, default
# 20000) from three sources at tolerances 0.005 to 0.2, and reports every run
# that fails. Needs a built build/examples/geodesic_ridge (scripts/demo.sh).
#   bash scripts/check_all_meshes.sh [MAX_FACES]
set -uo pipefail
cd "$(dirname "$0")/.."
max_faces=${1:-20000}
cli=./build/examples/geodesic_ridge
runs=0; failures=0
for mesh in ../shared/data/*.off; do
  faces=$(sed -n 2p "$mesh" | awk '{print $2}')
  [ "$faces" -le "$max_faces" ] || continue
  vertices=$(sed -n 2p "$mesh" | awk '{print $1}')
  for source in 0 $((vertices / 3)) $((2 * vertices / 3)); do
    for tol in 0.005 0.025 0.1 0.2; do
      runs=$((runs + 1))
      if ! out=$($cli "$mesh" --source-vertex $source --tolerance $tol 2>&1); then
        failures=$((failures + 1))
        echo "FAILED: $(basename "$mesh") --source-vertex $source --tolerance $tol: $(echo "$out" | tail -1)"
      fi
    done
  done
done
echo "$((runs - failures)) passed, $failures failed"
