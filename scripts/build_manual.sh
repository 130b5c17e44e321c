#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the manual (user manual and reference, doc/Geodesic_ridge/) with
# Doxygen, after its figures (doc/Geodesic_ridge/make_figures.sh), into
#   build-doc/html/index.html        (or DIR/html/index.html: build_manual.sh DIR)
# Every Doxygen warning is an error: they are printed, counted, and the script
# exits non-zero if there is any.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh --doc
out=${1:-build-doc}
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out/html"
bash doc/Geodesic_ridge/make_figures.sh "$out/figures"
status=0
GEODESIC_RIDGE_DOC_DIR="$out" doxygen doc/Geodesic_ridge/Doxyfile 2> "$out/doxygen_warnings.txt" || status=$?
warnings=$(grep -c . "$out/doxygen_warnings.txt" || true)
if [ "$status" -ne 0 ] || [ "$warnings" -ne 0 ]; then
  cat "$out/doxygen_warnings.txt" >&2
  echo "manual: doxygen exit status $status, $warnings warning lines (warnings are errors)" >&2
  exit 1
fi
echo "manual: 0 warnings; open $out/html/index.html"
