#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A batch killed (SIGKILL) at a random moment, three times, leaves only whole
# files: every DIR/*.polylines.txt line is 'n' and 3n numbers, every
# DIR/*.json parses. Then a run to the end over what the last one left: exit 0.
#   kill_batch.sh PROGRAM MESH OUT_DIR
set -u
program=$1 mesh=$2 out=$3
dir=$out/kill_batch
mkdir -p "$out"
sources=$out/kill_batch_sources.txt
printf '%s\n' 0 17 31 50 77 100 123 150 199 250 301 350 399 420 450 499 >"$sources"

check() # $1: what was done
{
  local f
  for f in "$dir"/*.polylines.txt; do
    [ -e "$f" ] || continue
    awk '{ if(NF < 4 || NF != 1 + 3 * $1) { bad = 1; exit } } END { exit bad }' "$f" ||
      { echo "$1: $f is not whole"; exit 1; }
  done
  for f in "$dir"/*.json; do
    [ -e "$f" ] || continue
    /usr/bin/python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$f" ||
      { echo "$1: $f does not parse"; exit 1; }
  done
}

for run in 1 2 3; do
  rm -rf "$dir"
  delay=$(printf '0.%03d' $((RANDOM % 300)))
  "$program" "$mesh" --sources "$sources" --out-dir "$dir" >/dev/null 2>&1 &
  pid=$!
  sleep "$delay"
  kill -KILL "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  written=$(ls "$dir" 2>/dev/null | grep -c -v '^summary.json$')
  check "killed after $delay s"
  echo "run $run: killed after $delay s, $written whole files"
done
"$program" "$mesh" --sources "$sources" --out-dir "$dir" >/dev/null || { echo "the full run failed"; exit 1; }
check "the full run"
[ "$(ls "$dir"/*.polylines.txt | wc -l)" = 16 ] || { echo "the full run: not 16 ridges"; exit 1; }
/usr/bin/python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); sys.exit(s["failed"] != 0 or len(s["sources"]) != 16)' \
  "$dir/summary.json" || { echo "the full run: bad summary.json"; exit 1; }
echo "the full run: 16 ridges, summary.json all ok"
