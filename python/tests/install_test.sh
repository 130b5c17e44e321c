#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The module installed the two ways the README gives, each then imported from
# a folder outside the repository and run on a mesh of data/:
#   install_test.sh cmake BUILD_DIR PYTHON WORK   cmake --install BUILD_DIR into WORK/prefix
#   install_test.sh pip SOURCE_DIR PYTHON WORK    a venv that sees Debian's packages, pip install, offline
set -euo pipefail
how=$1 dir=$2 python=$3 work=$4
data=$(cd "$(dirname "$0")/../../data" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
check='
import sys, geodesic_ridge as gr
V, F = gr.read_mesh(sys.argv[1])
r = gr.RidgeSolver(V, F).ridge(0)
assert r.statistics["statistics"]["ridge"]["cycles"] == 2, r
print("imported", gr.__file__, r)
'
if [ "$how" = cmake ]; then
  cmake --install "$dir" --prefix "$work/prefix" >/dev/null
  site=$(find "$work/prefix" -type d -name geodesic_ridge -path "*packages*" | head -1)
  PYTHONPATH=$(dirname "$site") "$python" -c "$check" "$data/torus_1k.off"
else
  "$python" -m venv --system-site-packages env
  env/bin/pip install --no-build-isolation --no-index -q "$dir"
  env/bin/python -c "$check" "$data/torus_1k.off"
fi
