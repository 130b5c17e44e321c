#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Behaviour check for refactoring: runs two builds of the command-line program
# (OLD and NEW) on every mesh of data/ and ../shared/data (up to MAX_FACES
# faces, default 20000), from a vertex source and a surface-point source, with
# both solvers, and compares every output: ridge and rough-cut polylines, ridge
# locations, the refined mesh (ASCII PLY), iso-lines, distance queries and the
# statistics' counts (timings excluded). Numbers must agree to 1e-9 relative to
# the mesh size; text must be identical.
#   bash scripts/compare_outputs.sh OLD_CLI NEW_CLI [MAX_FACES]
# SOLVERS (default "exact fmm") and EXTRA_ARGS (default none) change the runs,
# e.g. SOLVERS=vtp EXTRA_ARGS="--field cone" for the window propagation's cones.
# NEW_KEYS (comma-separated): statistics keys the new build added, left out of
# the comparison.
# Exit status 0 iff every run agrees.
set -uo pipefail
cd "$(dirname "$0")/.."
old=$(realpath "$1"); new=$(realpath "$2"); max_faces=${3:-20000}
work=$(mktemp -d); trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
runs=0; differences=0

compare() {  # compare FILE_A FILE_B SCALE: token by token, numbers to 1e-9*SCALE
  python3 - "$1" "$2" "$3" <<'EOF'
import json, os, re, sys
a_path, b_path, scale = sys.argv[1], sys.argv[2], float(sys.argv[3])
new_keys = set(k for k in os.environ.get('NEW_KEYS', '').split(',') if k)
def tokens(path):
    text = open(path).read()
    if path.endswith('.json'):  # counts only: drop timings
        data = json.loads(text)
        def strip(d):
            if isinstance(d, dict):
                return {k: strip(v) for k, v in d.items()
                        if 'time' not in k and 'second' not in k and k not in new_keys}
            return d
        text = json.dumps(strip(data), sort_keys=True)
    return re.findall(r'[^\s,:\[\]{}"]+', text)
a, b = tokens(a_path), tokens(b_path)
if len(a) != len(b):
    print(f"{len(a)} vs {len(b)} tokens"); sys.exit(1)
for i, (x, y) in enumerate(zip(a, b)):
    if x == y: continue
    try:
        if abs(float(x) - float(y)) <= 1e-9 * max(scale, 1.0): continue
    except ValueError: pass
    print(f"token {i}: {x} vs {y}"); sys.exit(1)
EOF
}

meshes=$(ls data/*.off; ls ../shared/data/*.off 2>/dev/null)
for mesh in $meshes; do
  # the bundled meshes are copies of shared ones: run each name once
  case "$mesh" in ../*) [ -e "data/$(basename "$mesh")" ] && continue ;; esac
  faces=$(sed -n 2p "$mesh" | awk '{print $2}')
  [ "$faces" -le "$max_faces" ] || continue
  vertices=$(sed -n 2p "$mesh" | awk '{print $1}')
  scale=$(awk 'NR>2 && NR<=2+n {for(i=1;i<=3;i++){v=$i<0?-$i:$i; if(v>m)m=v}} END{print m}' n="$vertices" "$mesh")
  # a surface point: the centroid of the middle face
  read -r fa fb fc < <(awk -v f=$((faces / 2)) -v n="$vertices" 'NR==3+n+f {print $2, $3, $4}' "$mesh")
  point=$(awk -v a="$fa" -v b="$fb" -v c="$fc" 'NR==3+a||NR==3+b||NR==3+c {x+=$1;y+=$2;z+=$3} END{printf "%.17g %.17g %.17g", x/3, y/3, z/3}' "$mesh")
  # queries: that centroid, and the first corner of the face a third into the file
  third=$((faces / 3))
  corner=$(awk -v f=$third -v n="$vertices" 'NR==3+n+f {print $2}' "$mesh")
  { echo "$((faces / 2)) $point"
    echo "$third $(awk -v v="$corner" 'NR==3+v {print $1, $2, $3}' "$mesh")"; } \
    > "$work/queries.txt"
  for source in "--source-vertex $((vertices / 3))" "--source-point $((faces / 2)) $point"; do
    for solver in ${SOLVERS:-exact fmm}; do
      runs=$((runs + 1))
      for side in old new; do
        d="$work/$side"; rm -rf "$d"; mkdir -p "$d"
        cli=$old; [ $side = new ] && cli=$new
        # shellcheck disable=SC2086
        "$cli" "$mesh" $source --solver $solver --tolerance 0.01 ${EXTRA_ARGS:-} \
          --ridge "$d/ridge.polylines.txt" --ridge-locations "$d/locations.txt" \
          --rough-cut "$d/rough.polylines.txt" --refined "$d/refined.ply" --ply-ascii \
          --isolines 7 "$d/isolines.polylines.txt" \
          --query "$work/queries.txt" --query-out "$d/queries.out.txt" \
          --stats "$d/stats.json" > "$d/stdout.txt" 2>&1
        echo $? > "$d/rc"
        [ "$(cat "$d/rc")" -eq 0 ] || echo "exit $(cat "$d/rc") ($side): $(tail -1 "$d/stdout.txt")"
      done
      what="$(basename "$mesh") $source --solver $solver"
      if ! cmp -s "$work/old/rc" "$work/new/rc"; then
        differences=$((differences + 1)); echo "DIFFERENT exit status: $what"; continue
      fi
      for f in ridge.polylines.txt locations.txt rough.polylines.txt refined.ply \
               isolines.polylines.txt queries.out.txt stats.json; do
        [ -e "$work/old/$f" ] || [ -e "$work/new/$f" ] || continue
        if ! msg=$(compare "$work/old/$f" "$work/new/$f" "$scale"); then
          differences=$((differences + 1)); echo "DIFFERENT $f: $what: $msg"
        fi
      done
    done
  done
done
echo "$runs runs, $differences differences"
[ "$differences" -eq 0 ]
