#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs every output of the region-wise field (refined mesh, iso-lines, ridge
# locations, queries, picture) on every mesh of ../shared/data, with fast
# marching on all of them and with the exact solver (and the cone field) on
# those up to MAX_EXACT_FACES faces (default 20000), from two sources each,
# and reports every run that fails or whose refined mesh leaves a ridge
# segment off its edges. Needs a built build/examples/geodesic_ridge.
#   bash scripts/check_field_all_meshes.sh [MAX_EXACT_FACES]
set -uo pipefail
cd "$(dirname "$0")/.."
max_exact=${1:-20000}
cli=./build/examples/geodesic_ridge
out=$(mktemp -d)
runs=0; failures=0
for mesh in ../shared/data/*.off; do
  faces=$(sed -n 2p "$mesh" | awk '{print $2}')
  vertices=$(sed -n 2p "$mesh" | awk '{print $1}')
  # queries: the three corners and the centroid of every 97th face (barycentric)
  awk -v F="$faces" 'BEGIN { for(f = 0; f < F; f += 97) printf "%d 1 0 0\n%d 0 1 0\n%d 0 0 1\n%d 0.25 0.25 0.5\n", f, f, f, f }' > "$out/q.txt"
  for solver in fmm exact; do
    if [ "$solver" = exact ] && [ "$faces" -gt "$max_exact" ]; then continue; fi
    extra=""
    [ "$solver" = exact ] && extra="--field cone"
    for source in 0 $((vertices / 2)); do
      runs=$((runs + 1))
      start=$(date +%s.%N)
      if ! log=$($cli "$mesh" --source-vertex $source --solver $solver $extra --refined "$out/r.ply" \
                 --isolines 20 "$out/i.txt" --ridge-locations "$out/l.txt" --query "$out/q.txt" \
                 --query-barycentric --query-out "$out/d.txt" --png "$out/p.png" --stats "$out/s.json" 2>&1); then
        failures=$((failures + 1))
        echo "FAILED: $(basename "$mesh") $solver source $source: $(echo "$log" | tail -1)"
        continue
      fi
      seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
      refined=$(grep -o '"refined_mesh": {[^}]*}' "$out/s.json")
      echo "$(basename "$mesh") $solver source $source: ${seconds}s $(wc -l < "$out/i.txt") iso-lines, $refined"
    done
  done
done
rm -rf "$out"
echo "$((runs - failures)) passed, $failures failed"
