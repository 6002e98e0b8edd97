#!/usr/bin/env bash
# Behaviour check for a restructuring: runs two builds of the tool on the same inputs and diffs
# every output, with the fields that are documented to change masked (wall-clock times:
# JSON "seconds"/"seconds_*", "time: ..." and the trailing seconds of "work: ..." lines).
#
#   bash scripts/compare_outputs.sh BEFORE/bin/sphtroch AFTER/bin/sphtroch
#
# Inputs: every case of data/reference/paper_cases.csv (classify, classify --json, nodes, trace,
# plot), the scene data/scenes/paper_figures.json (--explain and its files), atlas n = 2 grid 32
# (CSV, SVG, summary). Exits 0 when identical, 1 with the diff otherwise.
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
