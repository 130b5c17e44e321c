#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian packages Geodesic_ridge needs, when run as root; otherwise
# prints the one apt-get line to run. Exit status 0 iff everything is there.
#   --doc   also the packages that build the manual (scripts/build_manual.sh)
set -euo pipefail
packages=(g++ make cmake libcgal-dev libboost-graph-dev libgmp-dev libmpfr-dev catch2 libeigen3-dev ccache
          libboost-program-options-dev nlohmann-json3-dev libpng-dev libtbb-dev
          # the Python module (python/): for Debian's own python3
          python3-dev pybind11-dev python3-numpy python3-pytest python3-setuptools python3-wheel python3-venv
          python3-dask python3-distributed python3-meshio python3-matplotlib)
if [ "${1:-}" = "--doc" ]; then packages+=(doxygen graphviz); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" -eq 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "missing Debian packages; run:" >&2
  echo "  sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
