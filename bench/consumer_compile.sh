#!/usr/bin/env bash
# bench/consumer_compile.sh — what a C++ consumer pays to compile the README's example
# (bench/readme_example.cpp: classify() of report Fig. 5(f) and a sampled period) through the two
# routes of an installed sphtroch: header-only (pkg-config sphtroch-exact: the file parses CGAL and
# compiles the whole census) and compiled (pkg-config sphtroch-compiled: the file declares
# classify() and links libsphtroch_compiled). g++ -O2, one process per build, REPS runs each
# (default 3); prints the median wall time, the median CPU time (user + system: what the load of
# other processes changes least) and the median peak memory (/usr/bin/time -v), and the load.
#
#   bash bench/consumer_compile.sh PREFIX     # PREFIX: a `cmake --install` of a build with sphtroch_compiled
#
# Exit status 0; 1 when a build or a run of the example fails; 2 on bad arguments.
set -euo pipefail
[[ $# -eq 1 && -d $1 ]] || { echo "usage: bash bench/consumer_compile.sh PREFIX (an installed sphtroch)" >&2; exit 2; }
prefix=$(cd "$1" && pwd)
reps=${REPS:-3}
example=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/readme_example.cpp
pc_compiled=$(dirname "$(find "$prefix" -name sphtroch-compiled.pc | head -n 1)")
[[ -n $pc_compiled && $pc_compiled != . ]] || { echo "consumer_compile: no sphtroch-compiled.pc under $prefix" >&2; exit 2; }
export PKG_CONFIG_PATH=$pc_compiled:$prefix/share/pkgconfig
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

measure() {  # measure NAME FLAGS...: REPS builds of the example to $work/NAME, then one run
  local name=$1
  shift
  : >"$work/$name.s"
  : >"$work/$name.kb"
  : >"$work/$name.cpu"
  for ((i = 0; i < reps; ++i)); do
    /usr/bin/time -v -o "$work/time.txt" g++ -std=c++17 -O2 "$example" "$@" -o "$work/$name"
    awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (j = 1; j <= n; ++j) s = s * 60 + t[j]; print s}' \
      "$work/time.txt" >>"$work/$name.s"
    awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt" >>"$work/$name.kb"
    awk -F': ' '/User time|System time/ {s += $2} END {print s}' "$work/time.txt" >>"$work/$name.cpu"
  done
  LD_LIBRARY_PATH=$(pkg-config --variable=libdir sphtroch-compiled) "$work/$name" >/dev/null
  printf '%-12s median %6.1f s (CPU %6.1f s)  peak %5.0f MiB  (%d builds; load %s)\n' "$name" "$(median <"$work/$name.s")" \
    "$(median <"$work/$name.cpu")" "$(median <"$work/$name.kb" | awk '{print $1 / 1024}')" "$reps" \
    "$(cut -d' ' -f1-3 /proc/loadavg)"
}

# shellcheck disable=SC2046  # pkg-config's flags are words
measure header-only $(pkg-config --cflags --libs sphtroch-exact)
# shellcheck disable=SC2046
measure compiled $(pkg-config --cflags --libs sphtroch-compiled)
