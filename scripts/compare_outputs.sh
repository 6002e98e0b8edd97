#!/usr/bin/env bash
# Behaviour check for a restructuring: runs two builds of the tool on the same inputs and diffs
# every output, with the fields that are documented to change masked (wall-clock times:
# JSON "seconds"/"seconds_*", "time: ..." lines, the trailing seconds of "work: ..." lines and of
# scene's stage lines, crossings' "seconds_read"/"seconds_search" lines, and the time stamp in the
# FILE_NAME of a STEP file's header).
#
#   bash scripts/compare_outputs.sh BEFORE/bin/sphtroch AFTER/bin/sphtroch
#
# Inputs (each executable loads its own plugins, from lib/sphtroch next to its bin/):
# - gear trains: every case of data/reference/paper_cases.csv (classify, classify --json, nodes,
#   trace, plot); the scene data/scenes/paper_figures.json (--explain and its files); atlas n = 2
#   grid 32 (CSV, SVG, summary); a sharded atlas merged (CSV, summary, SVG in degrees);
#   boundaries (events, JSON, degrees, loci); crossings of a trace (text, JSON);
# - pictures: plot with --view, --labels, --markers, --size, --teeth, --style density, and a PNG;
# - CAD and data files of trace: DXF closed and open, OBJ, .npy, STEP closed (.step, --radius) and
#   open (.stp, --turns, --tolerance);
# - inverse design: identify, precision points (fixed frame, teeth, free axis, shards merged), fit
#   (text, JSON, shards merged);
# - chains: classify (text, JSON; three stages and a gear train), nodes (--radius, --degrees),
#   trace (CSV with --velocity --kinematics, --degrees, DXF, OBJ, .npy), boundaries along a family
#   (closed forms: A2 text and JSON, P1; slab searches: A3 text and JSON, A1 with a range end at
#   an event, not certified), export --urdf (file and stdout) and classify (text, JSON), nodes,
#   trace, plot --urdf of that file, plot (SVG, density, PNG);
# - clinostats: reports (text and JSON) with --window, --epsilon, --resolution, --coverage,
#   --nside, --start, tilted frames with phases, an off-centre --offset, single-axis and still
#   machines; --plot (SVG with and without --coverage, PNG); --trace (CSV, -o CSV with --offset
#   and --start, .npy); design (text with --coverage, JSON, --teeth), design --shard parts merged
#   (text, JSON);
# - tolerance: holds (text, JSON), changes (text), --teeth --tol-phase --samples --seed -o JSON;
# - refusals (stderr line and status) of classify, trace, atlas, boundaries, atlas-merge,
#   chain trace (.step), clinostat (--nside), clinostat merge (a repeated part) and tolerance.
# Exits 0 when identical, 1 with the diff otherwise.
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
  "$exe" crossings --input "$d/t.csv" >"$d/crossings.txt" 2>&1 || true
  "$exe" crossings --input "$d/t.csv" --json >"$d/crossings.json" 2>&1 || true
  "$exe" boundaries --n 3 --a2 pi/2 --degrees >"$d/boundaries_deg.txt" 2>&1 || true
  "$exe" atlas-merge "$d/shard3.csv" "$d/shard1.csv" "$d/shard2.csv" --svg "$d/merged.svg" --degrees \
    >"$d/merge_svg.txt" 2>&1 || true
  # Pictures: plot's options, a dense curve's density and hidden markers, a PNG.
  local p=$d/pictures
  mkdir -p "$p"
  "$exe" plot --a2 pi/3 --a3 pi/2 --n 13/5 --view 30deg,45deg --labels numbers --size 300 -o "$p/view.svg" >"$p/view.txt" 2>&1 || true
  "$exe" plot --a2 1 --a3 2 --n 13/5 --style density --size 240 -o "$p/density.svg" >"$p/density.txt" 2>&1 || true
  "$exe" plot --a2 1 --a3 2 --n 13/5 --markers none --view top -o "$p/top.svg" >"$p/top.txt" 2>&1 || true
  "$exe" plot --a2 1 --a3 2 --teeth 39:15 --view side -o "$p/teeth.svg" >"$p/teeth.txt" 2>&1 || true
  "$exe" plot --a2 1 --a3 2 --n 7/3 --view front --labels none --markers all -o "$p/front.png" >"$p/front.txt" 2>&1 || true
  # CAD and data files of a trace: DXF, OBJ, .npy, STEP.
  local c=$d/cad
  mkdir -p "$c"
  "$exe" trace --a2 1 --a3 2 --n 5/2 --samples 40 --radius 25 -o "$c/closed.dxf" >"$c/closed_dxf.txt" 2>&1 || true
  "$exe" trace --a2 pi/2 --a3 pi/3 --n -3/2 --turns 0.1 --format dxf >"$c/open.dxf" 2>&1 || true
  "$exe" trace --a2 1 --a3 2 --n 5/2 --samples 30 -o "$c/path.obj" >"$c/obj.txt" 2>&1 || true
  "$exe" trace --a2 1 --a3 2 --n 5/2 --samples 30 --velocity --kinematics -o "$c/path.npy" >"$c/npy.txt" 2>&1 || true
  "$exe" trace --a2 1 --a3 2 --n 5/2 --radius 25 -o "$c/closed.step" >"$c/closed_step.txt" 2>&1 || true
  "$exe" trace --a2 pi/2 --a3 pi/3 --n -3/2 --turns 0.5 --tolerance 1e-4 -o "$c/open.stp" >"$c/open_stp.txt" 2>&1 || true
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
  # Chains: census (three stages, a gear train), nodes, trace formats, events along families,
  # URDF written and read back, pictures.
  local h=$d/chain w=(--twists pi/2,pi/3,pi/4 --rates 1,1/2,-3/2 --phases 0,0.3,0) s3=(--twists 1.2,0.9,0.7 --rates 1,2,-3)
  mkdir -p "$h"
  "$exe" chain classify "${w[@]}" >"$h/wrist.txt" 2>&1 || true
  "$exe" chain classify "${w[@]}" --json >"$h/wrist.json" 2>&1 || true
  "$exe" chain classify --twists 1.1,0.7 --rates 1,5/2 >"$h/train.txt" 2>&1 || true
  "$exe" chain classify --twists 1.1,0.7 --rates 1,5/2 --phases 0.2,0.3 --json >"$h/train.json" 2>&1 || true
  "$exe" chain nodes "${w[@]}" --radius 25 --degrees >"$h/nodes.csv" 2>&1 || true
  "$exe" chain trace "${w[@]}" --samples 12 --velocity --kinematics >"$h/trace.csv" 2>&1 || true
  "$exe" chain trace "${w[@]}" --samples 9 --degrees -o "$h/trace_deg.csv" >"$h/trace_deg.txt" 2>&1 || true
  "$exe" chain trace "${w[@]}" --samples 20 --radius 25 -o "$h/path.dxf" >"$h/dxf.txt" 2>&1 || true
  "$exe" chain trace "${w[@]}" --samples 20 -o "$h/path.obj" >"$h/obj.txt" 2>&1 || true
  "$exe" chain trace "${w[@]}" --samples 20 --velocity -o "$h/path.npy" >"$h/npy.txt" 2>&1 || true
  "$exe" chain boundaries --twists pi/2,1 --rates 1,3 --vary A2:0:pi >"$h/events_a2.txt" 2>&1 || true
  "$exe" chain boundaries --twists pi/2,1 --rates 1,3 --vary A2:0.5:1.5 --json >"$h/events_a2.json" 2>&1 || true
  "$exe" chain boundaries --twists pi/2,1 --rates 1,3 --vary P1:0:pi >"$h/events_p1.txt" 2>&1 || true
  "$exe" chain boundaries "${s3[@]}" --vary A3:0.8:0.84 >"$h/events_a3_cusp.txt" 2>&1 || true
  "$exe" chain boundaries "${s3[@]}" --vary A3:0.9:0.94 --json >"$h/events_a3_tangency.json" 2>&1 || true
  "$exe" chain boundaries --twists pi/2,1 --rates 1,3 --vary A1:1:1.3 >"$h/events_a1_end.txt" 2>&1 || true
  "$exe" chain export "${w[@]}" --urdf "$h/wrist.urdf" >"$h/export.txt" 2>&1 || true
  "$exe" chain export --twists pi/2,1.2 --rates 2,-3 --name geared --urdf - >"$h/export_stdout.urdf" 2>&1 || true
  local u=(--urdf "$h/wrist.urdf" --from base_link --to tool)
  "$exe" chain classify "${u[@]}" >"$h/urdf.txt" 2>&1 || true
  "$exe" chain classify "${u[@]}" --json >"$h/urdf.json" 2>&1 || true
  "$exe" chain nodes "${u[@]}" >"$h/urdf_nodes.csv" 2>&1 || true
  "$exe" chain trace --urdf "$h/wrist.urdf" --from base_link --to link_3 --axis 0,1,0 --samples 6 >"$h/urdf_trace.csv" 2>&1 || true
  "$exe" chain plot "${u[@]}" --view top --labels numbers -o "$h/urdf.svg" >"$h/urdf_plot.txt" 2>&1 || true
  "$exe" chain plot "${w[@]}" -o "$h/wrist.svg" >"$h/wrist_plot.txt" 2>&1 || true
  "$exe" chain plot "${w[@]}" --style density --size 200 -o "$h/wrist_density.svg" >"$h/wrist_density.txt" 2>&1 || true
  "$exe" chain plot --twists 1.1,0.7 --rates 1,5/2 -o "$h/train.png" >"$h/train_png.txt" 2>&1 || true
  # Clinostats: reports, pictures, gravity traces, design (whole, gear-driven, parts merged).
  local m=$d/clinostat
  mkdir -p "$m"
  "$exe" clinostat --outer 1.33 --inner 2 --window 600 --epsilon 0.01 >"$m/report.txt" 2>&1 || true
  "$exe" clinostat --outer 1.33 --inner 2 --window 600 --epsilon 0.01 --coverage 600 --nside 4 --json >"$m/report.json" 2>&1 || true
  "$exe" clinostat --outer 1.33 --inner 2 --coverage 300 --nside 2 --start 100 >"$m/coverage.txt" 2>&1 || true
  "$exe" clinostat --outer 1 --inner 2 --tilt 75 --frame-angle 80 --phase-outer 10 --phase-inner -20 --window 120 --epsilon 0.01 \
    >"$m/tilted.txt" 2>&1 || true
  "$exe" clinostat --outer 1 --inner 2 --offset 0.05,0,0.02 --window 120 --epsilon 0.01 --resolution 2 --json >"$m/offset.json" 2>&1 || true
  "$exe" clinostat --outer 2.5 --inner 0 --json >"$m/single_axis.json" 2>&1 || true
  "$exe" clinostat --outer 0 --inner 2.5 >"$m/still.txt" 2>&1 || true
  "$exe" clinostat --outer 1.33 --inner 2 --epsilon 0.01 --coverage 600 --nside 4 --plot "$m/dwell.svg" >"$m/plot.txt" 2>&1 || true
  "$exe" clinostat --outer 1 --inner 2 --epsilon 0.01 --plot "$m/period.svg" >"$m/plot_period.txt" 2>&1 || true
  "$exe" clinostat --outer 1.618 --inner 1 --coverage 120 --nside 4 --plot "$m/dwell.png" >"$m/plot_png.txt" 2>&1 || true
  "$exe" clinostat --outer 1.33 --inner 2 --trace --duration 60 --samples 7 >"$m/trace.csv" 2>&1 || true
  "$exe" clinostat --outer 1.33 --inner 2 --offset 0.1,0,0 --trace --duration 60 --samples 5 --start 30 -o "$m/trace_offset.csv" \
    >"$m/trace_offset.txt" 2>&1 || true
  "$exe" clinostat --outer 1.33 --inner 2 --trace --duration 60 --samples 5 -o "$m/trace.npy" >"$m/trace_npy.txt" 2>&1 || true
  local g=(--outer 1:2 --inner 0:2 --step 0.5 --window 600 --epsilon 0.01 --coverage 300 --nside 4)
  "$exe" clinostat design --outer 1:3 --inner 1:3 --step 0.5 --window 3600 --epsilon 0.01 --coverage 600 --nside 4 --top 3 \
    >"$m/design.txt" 2>&1 || true
  "$exe" clinostat design "${g[@]}" --json >"$m/design.json" 2>&1 || true
  "$exe" clinostat design --outer 0.5:3 --inner 0.5:3 --step 0.5 --teeth 10..30 --window 600 --epsilon 0.01 --top 4 -o "$m/teeth.txt" \
    >"$m/teeth_stdout.txt" 2>&1 || true
  for k in 1 2 3; do "$exe" clinostat design "${g[@]}" --shard "$k/3" --json -o "$m/part$k.json" >/dev/null 2>&1 || true; done
  "$exe" clinostat merge "$m/part3.json" "$m/part1.json" "$m/part2.json" --top 5 >"$m/merged.txt" 2>&1 || true
  "$exe" clinostat merge "$m/part2.json" "$m/part3.json" "$m/part1.json" --json >"$m/merged.json" 2>&1 || true
  # Tolerance: a box that holds, one that a boundary crosses, sampled trains.
  local o=$d/tolerance
  mkdir -p "$o"
  "$exe" tolerance --a2 1 --a3 2 --n 5/2 --tol-a2 0.05 --tol-a3 0.05 --degrees >"$o/holds.txt" 2>&1 || true
  "$exe" tolerance --a2 1 --a3 2 --n 5/2 --tol-a2 0.05 --tol-a3 0.05 --degrees --json >"$o/holds.json" 2>&1 || true
  "$exe" tolerance --a2 pi/2 --a3 0.33 --n 3 --tol-a2 0.001 --tol-a3 0.02 >"$o/changes.txt" 2>&1 || true
  "$exe" tolerance --a2 1.1 --a3 0.7 --teeth 39:15 --phase 0.2 --tol-a2 0.002 --tol-a3 0.002 --tol-phase 0.01 --samples 40 --seed 7 \
    --json -o "$o/sampled.json" >"$o/sampled_stdout.txt" 2>&1 || true
  # Refusals: the one stderr line and the status of each.
  local k=0
  for args in "classify --n 0 --a2 1 --a3 1" "classify --n 2 --a2 4 --a3 1" "trace --n 2 --a2 1 --a3 1 --turns 2e6" \
              "atlas --n 2 --grid 8 --a2 1:0.5" "boundaries --n 3 --a2 '1 :2'" "atlas-merge $d/missing.csv" \
              "trace --n 2 --a2 1 --a3 1 --turns x" "chain trace --twists pi/2,1 --rates 1,3 -o $d/chain.step" \
              "clinostat --outer 1 --inner 2 --coverage 60 --nside 3" \
              "clinostat merge $m/part1.json $m/part1.json $m/part2.json" \
              "tolerance --a2 1 --a3 2 --n 5/2 --tol-a2 -0.1 --tol-a3 0.1"; do
    k=$((k + 1))
    (eval "\"$exe\" $args" >"$d/refusal$k.out" 2>"$d/refusal$k.err"; echo "status $?" >>"$d/refusal$k.err") || true
    sed -i "s|$d|DIR|g" "$d/refusal$k.err"
  done
  # Mask the wall-clock fields.
  find "$d" -type f \( -name '*.txt' -o -name '*.json' \) -exec sed -i -E \
    -e 's/("seconds[a-z_]*": )[-0-9.e+]+/\1T/' -e 's/^(time: ).*/\1T/' -e 's/^(work: .*), [0-9.e+-]+ s$/\1, T s/' \
    -e 's/^( *[a-z_]+ +[0-9]+ points evaluated.*root evaluations), [0-9.e+-]+ s$/\1, T s/' \
    -e 's/^( *total: .*), [0-9.e+-]+ s$/\1, T s/' -e 's/^(seconds_(read|search) ).*/\1T/' {} +
  # The time stamp of a STEP file (the second field of FILE_NAME, in the header).
  find "$d" -type f \( -name '*.step' -o -name '*.stp' \) -exec sed -i -E \
    -e "0,/^ENDSEC;/ s/'[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}'/'T'/" {} +
}

before=$(realpath "$1") after=$(realpath "$2")
run_all "$before" "$work/before"
run_all "$after" "$work/after"
if diff -r "$work/before" "$work/after"; then
  echo "compare_outputs: identical ($(find "$work/after" -type f | wc -l) files, times masked)"
else
  exit 1
fi
