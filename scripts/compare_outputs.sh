#!/usr/bin/env bash
# Behaviour check for a restructuring: runs two builds of the tool on the same inputs and diffs
# every output, with the fields that are documented to change masked (wall-clock times:
# JSON "seconds"/"seconds_*", "time: ..." and the trailing seconds of "work: ..." lines).
#
#   bash scripts/compare_outputs.sh BEFORE/bin/sphtroch AFTER/bin/sphtroch
#
# Inputs: every case of data/reference/paper_cases.csv (classify, classify --json, nodes, trace,
# plot), the scene data/scenes/paper_figures.json (--explain and its files), atlas n = 2 grid 32
# (CSV, SVG, summary), a sharded atlas merged, boundaries (events, JSON, loci), crossings of a
# trace, and refusals (stderr line and status). Exits 0 when identical, 1 with the diff otherwise.
set -euo pipefail
[[ $# -eq 2 ]] || { echo "usage: bash scripts/compare_outputs.sh BEFORE_EXE AFTER_EXE" >&2; exit 2; }
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

run_all() {
  local exe=$1 d=$2
  mkdir -p "$d"
  tail -n +2 "$root/data/reference/paper_cases.csv" | while IFS=, read -r id nn nd a2 a3 _rest; do
    local args=(--a2 "$a2" --a3 "$a3" --n "$nn/$nd")
    "$exe" classify "${args[@]}" >"$d/$id.classify.txt" 2>&1 || true
    "$exe" classify "${args[@]}" --json >"$d/$id.json" 2>&1 || true
    "$exe" nodes "${args[@]}" >"$d/$id.nodes.csv" 2>&1 || true
    "$exe" trace "${args[@]}" >"$d/$id.trace.csv" 2>&1 || true
    "$exe" plot "${args[@]}" -o "$d/$id.svg" >/dev/null 2>&1 || true
  done
  mkdir -p "$d/scene"
  (cd "$d" && "$exe" scene "$root/data/scenes/paper_figures.json" --output-dir scene --explain >scene.txt 2>&1) || true
  "$exe" atlas --n 2 --grid 32 -o "$d/atlas.csv" --svg "$d/atlas.svg" >"$d/atlas.txt" 2>&1 || true
  # Sharded atlas merged back, boundaries (events and loci), crossings of a trace.
  for k in 1 2 3; do "$exe" atlas --n -5/3 --grid 24 --shard "$k/3" -o "$d/shard$k.csv" >/dev/null 2>&1 || true; done
  "$exe" atlas-merge "$d/shard2.csv" "$d/shard1.csv" "$d/shard3.csv" -o "$d/merged.csv" >"$d/merge.txt" 2>&1 || true
  "$exe" boundaries --n 3 --a2 pi/2 >"$d/boundaries.txt" 2>&1 || true
  "$exe" boundaries --n 7/5 --a2 1.1 --json >"$d/boundaries.json" 2>&1 || true
  "$exe" boundaries --n -5/2 --a2 0.2:3 --steps 60 >"$d/loci.csv" 2>&1 || true
  "$exe" trace --n 5/2 --a2 pi/3 --a3 pi/2 --samples 4000 -o "$d/t.csv" >/dev/null 2>&1 || true
  "$exe" crossings "$d/t.csv" >"$d/crossings.txt" 2>&1 || true
  # Inverse design: identify, precision points (fixed frame, teeth, free axis, shards merged), fit
  # (text, JSON, shards merged).
  "$exe" trace --n -7/3 --a2 0.5 --a3 2.5 --phase 1 --turns 3 >"$d/timed.csv" 2>/dev/null || true
  "$exe" synth identify --input "$d/timed.csv" >"$d/identify.txt" 2>&1 || true
  "$exe" trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 40 2>/dev/null | sed -n '3p;12p;30p' | cut -d, -f2-4 \
    | (echo x,y,z; cat) >"$d/pts3.csv"
  "$exe" synth points --input "$d/pts3.csv" --n 1/2 >"$d/points.txt" 2>&1 || true
  "$exe" synth points --input "$d/pts3.csv" --teeth 12:24 --json >"$d/points_teeth.json" 2>&1 || true
  for k in 1 2; do "$exe" synth points --input "$d/pts3.csv" --ratios 2,2 --shard "$k/2" --json -o "$d/pp$k.json" >/dev/null 2>&1 || true; done
  "$exe" synth merge "$d/pp2.json" "$d/pp1.json" >"$d/points_merged.json" 2>&1 || true
  "$exe" trace --n 1 --a2 1.2 --a3 0.8 --phase 0.5 --samples 50 2>/dev/null | sed -n '3p;11p;20p;34p;45p' \
    | awk -F, '{print $3","$4","$2}' | (echo x,y,z; cat) >"$d/pts5.csv"
  "$exe" synth points --input "$d/pts5.csv" --n 1 --free-axis >"$d/free_axis.txt" 2>&1 || true
  "$exe" trace --n 2 --a2 1.1 --a3 0.9 --phase 0.4 --samples 300 2>/dev/null | cut -d, -f2-4 >"$d/path.csv"
  "$exe" synth fit --input "$d/path.csv" --n 2 --nodes 4 --candidates 3 >"$d/fit.txt" 2>&1 || true
  "$exe" synth fit --input "$d/path.csv" --n 2 --json >"$d/fit.json" 2>&1 || true
  for k in 1 2; do "$exe" synth fit --input "$d/path.csv" --ratios 2,1 --shard "$k/2" --json -o "$d/pf$k.json" >/dev/null 2>&1 || true; done
  "$exe" synth merge "$d/pf1.json" "$d/pf2.json" >"$d/fit_merged.json" 2>&1 || true
  # Refusals: the one stderr line and the status of each.
  local k=0
  for args in "classify --n 0 --a2 1 --a3 1" "classify --n 2 --a2 4 --a3 1" "trace --n 2 --a2 1 --a3 1 --turns 2e6" \
              "atlas --n 2 --grid 8 --a2 1:0.5" "boundaries --n 3 --a2 '1 :2'" "atlas-merge $d/missing.csv" \
              "trace --n 2 --a2 1 --a3 1 --turns x"; do
    k=$((k + 1))
    (eval "\"$exe\" $args" >"$d/refusal$k.out" 2>"$d/refusal$k.err"; echo "status $?" >>"$d/refusal$k.err") || true
    sed -i "s|$d|DIR|g" "$d/refusal$k.err"
  done
  # Mask the wall-clock fields.
  find "$d" -type f \( -name '*.txt' -o -name '*.json' \) -exec sed -i -E \
    -e 's/("seconds[a-z_]*": )[-0-9.e+]+/\1T/' -e 's/^(time: ).*/\1T/' -e 's/^(work: .*), [0-9.e+-]+ s$/\1, T s/' \
    -e 's/^( *[a-z_]+ +[0-9]+ points evaluated.*root evaluations), [0-9.e+-]+ s$/\1, T s/' \
    -e 's/^( *total: .*), [0-9.e+-]+ s$/\1, T s/' {} +
}

before=$(realpath "$1") after=$(realpath "$2")
run_all "$before" "$work/before"
run_all "$after" "$work/after"
if diff -r "$work/before" "$work/after"; then
  echo "compare_outputs: identical ($(find "$work/after" -type f | wc -l) files, times masked)"
else
  exit 1
fi
