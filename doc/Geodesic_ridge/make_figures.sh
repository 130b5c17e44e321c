#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes every figure of the manual from the command-line program's own output
# (--png: the mesh from two opposite sides coloured by the distance, the ridge
# red, the rough cut locus white, the source green), on the meshes of data/.
#
#   bash doc/Geodesic_ridge/make_figures.sh OUT_DIR
#
# Builds build/examples/geodesic_ridge first (as scripts/demo.sh does), unless
# GEODESIC_RIDGE_CLI names a program already built. The figures' names are
# those that doc/Geodesic_ridge/*.txt show with \image.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:?usage: make_figures.sh OUT_DIR}
mkdir -p "$out"
cli=${GEODESIC_RIDGE_CLI:-}
if [ -z "$cli" ]; then
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$root/build" --target geodesic_ridge -j2
  cli=$root/build/examples/geodesic_ridge
fi

# figure NAME MESH ARGS...: OUT_DIR/NAME.png, and what the program said in OUT_DIR/NAME.log
figure() {
  local name=$1 mesh=$2
  shift 2
  "$cli" "$root/data/$mesh" "$@" --png "$out/$name.png" > "$out/$name.log"
  echo "figure $name.png: $mesh $*"
}

# introduction: the demo's mesh and source (genus 2, four cycles)
figure intro_eight eight.off --source-vertex 3
# stage 1: the cut graph K at a small and a large tolerance
figure stage1_teddy_tolerance_0.005 teddy_3k.off --source-vertex 0 --tolerance 0.005
figure stage1_teddy_tolerance_0.1 teddy_3k.off --source-vertex 0 --tolerance 0.1
# stage 2: the field of the lowest copies, split along the ridge (iso-line bands)
figure stage2_torus torus_1k.off --source-vertex 0
# stage 3: the ridge on genus 3 (six cycles)
figure stage3_3holes 3holes_7k.off --source-vertex 0
# the cone field's ridge against the linear one, and the fast-marching solver
figure cone_bunny_linear bunny_1k.off --source-vertex 0 --linear-ridge
figure cone_bunny_cone bunny_1k.off --source-vertex 0 --field cone
figure solvers_bunny_fmm bunny_1k.off --source-vertex 0 --solver fmm
