#!/usr/bin/env bash
# Regenerate the report's figure cases as SVG pictures: one `sphtroch plot` per row of
# data/reference/paper_cases.csv, written to data/figures/<id>.svg.
#
#   bash scripts/paper_figures.sh                  # uses build/bin/sphtroch
#   bash scripts/paper_figures.sh path/to/sphtroch # another binary
#   PNG=1 bash scripts/paper_figures.sh            # also data/figures/<id>.png (needs rsvg-convert,
#                                                  # Debian package librsvg2-bin)
#
# The reference table keeps the report's symbolic angles (pi/2, 2pi/3, a_p); they are passed on
# as typed, with the pitch cone "a_p" spelled the way the command line accepts it ("ap").
# Exit status: 0 when every case was drawn, 1 when any failed (each failure is named), 2 for
# a missing binary or table.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

bin=${1:-build/bin/sphtroch}
table=data/reference/paper_cases.csv
out_dir=data/figures

if [[ ! -x $bin ]]; then
  echo "paper_figures: no executable at '$bin' (build it first: bash scripts/dev.sh run)" >&2
  exit 2
fi
if [[ ! -r $table ]]; then
  echo "paper_figures: cannot read $table" >&2
  exit 2
fi
mkdir -p "$out_dir"

want_png=${PNG:-0}
if [[ $want_png == 1 ]] && ! command -v rsvg-convert >/dev/null 2>&1; then
  echo "paper_figures: PNG=1 but rsvg-convert is missing (apt-get install librsvg2-bin); writing SVG only" >&2
  want_png=0
fi

drawn=0
failed=()
# Columns: id,n_num,n_den,a2_symbolic,a3_symbolic,a2_rad,a3_rad,nodes,cusps,source (the last
# one quoted and containing commas: it lands in `rest` and is not used).
while IFS=, read -r id n_num n_den a2 a3 _a2_rad _a3_rad _nodes _cusps rest; do
  [[ $id == id ]] && continue  # header
  [[ -z $id ]] && continue
  a3_arg=${a3//a_p/ap}  # a_p -> ap, pi-a_p -> pi-ap
  svg="$out_dir/$id.svg"
  if "$bin" plot --a2 "$a2" --a3 "$a3_arg" --n "$n_num/$n_den" -o "$svg" </dev/null; then
    echo "$id: a2 = $a2, a3 = $a3, n = $n_num/$n_den -> $svg"
    drawn=$((drawn + 1))
    if [[ $want_png == 1 ]]; then
      rsvg-convert -b white "$svg" -o "${svg%.svg}.png" || failed+=("$id (png)")
    fi
  else
    echo "paper_figures: $id failed: $bin plot --a2 $a2 --a3 $a3_arg --n $n_num/$n_den -o $svg" >&2
    failed+=("$id")
  fi
done <"$table"

echo "paper_figures: $drawn figure(s) in $out_dir"
if ((${#failed[@]} > 0)); then
  echo "paper_figures: failed: ${failed[*]}" >&2
  exit 1
fi
