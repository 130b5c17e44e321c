#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds and runs one libFuzzer target of fuzz/ (clang++, ASan + UBSan):
#   bash scripts/fuzz.sh --list            the target names
#   bash scripts/fuzz.sh TARGET SECONDS    fuzz TARGET for SECONDS
# The binary goes to build-fuzz/fuzz_TARGET; the fuzzer starts from a copy of
# fuzz/corpus/TARGET in build-fuzz/corpus-TARGET and writes its new inputs
# there (not into the repository). A crash is written to
# build-fuzz/crash-TARGET-*; minimize it (the binary with -minimize_crash=1)
# and commit it to fuzz/corpus/TARGET, where ctest -R fuzz.regression (g++, CI)
# runs it. Extra arguments after SECONDS go to libFuzzer.
set -euo pipefail
cd "$(dirname "$0")/.."

targets=$(ls fuzz/fuzz_*.cpp | sed -n 's|fuzz/fuzz_\(.*\)\.cpp|\1|p' | grep -vx regression)
if [ "${1:-}" = "--list" ]; then
  echo "$targets"
  exit 0
fi
if [ $# -lt 2 ] || ! echo "$targets" | grep -qx "$1" || ! [[ "$2" =~ ^[0-9]+$ ]]; then
  echo "usage: bash scripts/fuzz.sh --list | TARGET SECONDS [LIBFUZZER_ARGS...]" >&2
  echo "targets: $(echo $targets)" >&2
  exit 2
fi
target=$1 seconds=$2
shift 2

# clang++ and the libFuzzer runtime (Debian: libclang-rt-14-dev; older: libfuzzer-14-dev)
cxx=$(command -v clang++ || command -v clang++-14 || true)
have_runtime() {
  [ -n "$cxx" ] && echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }' |
    "$cxx" -x c++ -fsanitize=fuzzer - -o /tmp/geodesic_ridge_fuzz_probe.$$ 2>/dev/null
}
if ! have_runtime; then
  packages="clang-14 libclang-rt-14-dev"
  if [ "$(id -u)" -eq 0 ]; then
    apt-get update -q && { apt-get install -y -q $packages || apt-get install -y -q clang-14 libfuzzer-14-dev; }
    cxx=$(command -v clang++ || command -v clang++-14 || true)
    have_runtime || { echo "fuzz.sh: no working clang++ -fsanitize=fuzzer after the install" >&2; exit 1; }
  else
    echo "fuzz.sh: clang++ with libFuzzer is missing; install it with:" >&2
    echo "  sudo apt-get install $packages   (or clang-14 libfuzzer-14-dev)" >&2
    exit 1
  fi
fi
rm -f /tmp/geodesic_ridge_fuzz_probe.$$

mkdir -p build-fuzz
bin=build-fuzz/fuzz_$target
if [ ! -x "$bin" ] || [ -n "$(find fuzz include examples/cli -newer "$bin" -name '*.h' -o -newer "$bin" -name "fuzz_$target.cpp" | head -1)" ]; then
  echo "building $bin (a CGAL translation unit: a minute or two)"
  # -frounding-math and the GMP defines as the CMake build (CGAL's interval arithmetic needs them)
  "$cxx" -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-omit-frame-pointer -frounding-math \
    -DCGAL_USE_GMPXX=1 -I include -isystem /usr/include/eigen3 \
    "fuzz/fuzz_$target.cpp" -o "$bin" -lboost_program_options -lgmpxx -lmpfr -lgmp
fi

corpus=build-fuzz/corpus-$target
mkdir -p "$corpus"
cp -n fuzz/corpus/"$target"/* "$corpus"/ 2>/dev/null || true
log=build-fuzz/fuzz-$target.log
status=0
"$bin" "$corpus" -max_total_time="$seconds" -rss_limit_mb=1024 -timeout=10 \
  -artifact_prefix="build-fuzz/crash-$target-" -print_final_stats=1 "$@" 2>&1 | tee "$log" || status=${PIPESTATUS[0]}
echo "----"
# libFuzzer's last status line (cov: edges, ft: features, exec/s) and final stats
grep -E '^#[0-9]+' "$log" | tail -1 || true
grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)' "$log" || true
[ "$status" -eq 0 ] || echo "fuzz.sh: $target found something (exit $status), see $log and build-fuzz/crash-$target-*" >&2
exit "$status"
