#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Every named parameter that is not in the paper, on and off: runs
# bench_ridge_accuracy (exact solver; precision and recall against the exact
# reference ridge) and bench_geodesic_ridge (time per stage) once with the
# defaults and once per changed option, and prints each run's summary rows.
#   bash benchmark/measure_options.sh [BUILD_DIR] [SOURCES_PER_MESH]
# Needs a Release build of the benchmarks (default build/). About 3 minutes per
# variant with 4 sources per mesh on the 14 shared meshes up to 20k faces.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}; sources=${2:-4}
variants=(
  "defaults|"
  "predicted_extension off|--predicted 0"
  "tree_from_solver on|--tree-from-solver 1"
  "leaf_curvature off|--leaf-curvature 0"
  "branch_curvature off|--branch-curvature 0"
  "kink_angle off|--kink-angle 0"
  "minimum_spur_angle off|--spur-angle 0"
)
for v in "${variants[@]}"; do
  name=${v%%|*}; flags=${v#*|}
  echo "## $name ($flags)"
  # shellcheck disable=SC2086
  "$build/benchmark/bench_ridge_accuracy" --solver exact --sources-per-mesh "$sources" --random-sources 1 \
      --max-faces 20000 $flags 2>/dev/null | grep -A3 "^| solver | pairs"
  # shellcheck disable=SC2086
  "$build/benchmark/bench_geodesic_ridge" --max-faces 20000 $flags 2>/dev/null |
      awk -F'|' 'NR > 2 && NF > 10 { total += $14; n++ } END { printf "bench_geodesic_ridge: %d meshes, total %.2f s\n\n", n, total }'
done
