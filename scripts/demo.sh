#!/usr/bin/env bash
# Builds the geodesic_ridge program and runs it on the bundled default mesh.
# Outputs go to out/ (see the last lines this prints).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target geodesic_ridge -j2
mkdir -p out
./build/examples/geodesic_ridge data/bunny_1k.off --source-vertex 0 \
    --rough-cut out/bunny_1k.rough_cut.polylines.txt --stats out/bunny_1k.stats.json
echo
echo "Outputs are in $(pwd)/out:"
echo "  out/bunny_1k.rough_cut.polylines.txt  the rough cut locus (CGAL polylines: n x1 y1 z1 ... per line)"
echo "  out/bunny_1k.stats.json               counts, timings and parameters"
