#!/usr/bin/env bash
# bench/median_time.sh — the time and memory of a whole command, the way docs/performance.md
# measures them: the command runs N times in turn, each run a whole process under
# `/usr/bin/time -v` (Debian package `time`), its stdout and stderr discarded. Prints one line:
#
#   median 13.2 ms, min 12.1 ms, max 15.0 ms; cpu median 12.0 ms; peak RSS median 13.2 MiB; exit 0; 5 runs; load 1.41 before, 1.38 after
#
# - wall time: bash's EPOCHREALTIME (microseconds) around each run, so it includes the start of
#   `/usr/bin/time` itself (about a millisecond, more on a loaded machine); the median of the N runs (the mean of the middle two
#   when N is even), and the smallest and largest run;
# - cpu: user + system seconds of the run as `/usr/bin/time -v` reports them (10 ms resolution);
# - peak RSS: its "Maximum resident set size", in MiB (1024 KiB);
# - exit: the command's exit status (every distinct status, "0/3" when runs differ); a command
#   that fails is measured all the same (a certified "exit 3" is a result, not an error);
# - load: the 1-minute load average (/proc/loadavg) before the first run and after the last
#   (the machine is shared: a load above its cores inflates the times).
# No warm-up run: the first run pays a cold page cache; give N >= 3 and read the median.
#
#   bash bench/median_time.sh -n N -- COMMAND [ARG...]    # N: 1 .. 1000
#
# Exit status 0 when the command was measured, whatever its own status; 2 on bad arguments (one
# line on stderr naming the argument, its value and what is valid; nothing on stdout).
set -euo pipefail

bad() {  # bad ARGUMENT VALUE WHAT: the one-line refusal
  echo "median_time.sh: $1 = $2: $3; usage: bash bench/median_time.sh -n N -- COMMAND [ARG...]" >&2
  exit 2
}

[[ $# -ge 1 && $1 == -n ]] || bad "first argument" "${1-(none)}" "must be -n"
[[ $# -ge 2 ]] || bad "-n" "(none)" "valid: a whole number 1 .. 1000"
[[ $2 =~ ^[0-9]{1,4}$ ]] && ((10#$2 >= 1 && 10#$2 <= 1000)) || bad "-n" "$2" "valid: a whole number 1 .. 1000"
runs=$((10#$2))
[[ $# -ge 3 && $3 == -- ]] || bad "third argument" "${3-(none)}" "must be --, then the command"
shift 3
[[ $# -ge 1 ]] || bad "command" "(none)" "give the command to measure after --"
if [[ $1 == */* ]]; then [[ -f $1 && -x $1 ]]; else type -P -- "$1" >/dev/null; fi ||
  bad "command" "$1" "not an executable file or a name on PATH (for a shell line: bash -c '...')"
[[ -x /usr/bin/time ]] || bad "/usr/bin/time" "(missing)" "install Debian's package time"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
load_before=$(cut -d' ' -f1 /proc/loadavg)
for ((i = 0; i < runs; ++i)); do
  start=$EPOCHREALTIME
  status=0
  /usr/bin/time -v -o "$work/time.txt" -- "$@" >/dev/null 2>&1 || status=$?
  end=$EPOCHREALTIME
  echo "$start $end" | awk '{printf "%.6f\n", $2 - $1}' >>"$work/wall"
  awk -F': ' '/User time \(seconds\)/ {u = $2} /System time \(seconds\)/ {s = $2} END {printf "%.2f\n", u + s}' \
    "$work/time.txt" >>"$work/cpu"
  awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt" >>"$work/rss"
  echo "$status" >>"$work/status"
done
load_after=$(cut -d' ' -f1 /proc/loadavg)

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
seconds() {  # seconds X: X s with 3 significant digits, in ms below 1 s
  awk -v s="$1" 'BEGIN {if (s < 1) printf "%.3g ms", s * 1000; else if (s < 100) printf "%.3g s", s; else printf "%.0f s", s}'
}
wall_median=$(median <"$work/wall")
wall_min=$(sort -g "$work/wall" | head -n 1)
wall_max=$(sort -g "$work/wall" | tail -n 1)
rss_mib=$(median <"$work/rss" | awk '{printf "%.1f", $1 / 1024}')
statuses=$(sort -n -u "$work/status" | paste -s -d/)
printf 'median %s, min %s, max %s; cpu median %s; peak RSS median %s MiB; exit %s; %d run%s; load %s before, %s after\n' \
  "$(seconds "$wall_median")" "$(seconds "$wall_min")" "$(seconds "$wall_max")" "$(seconds "$(median <"$work/cpu")")" \
  "$rss_mib" "$statuses" "$runs" "$( ((runs > 1)) && echo s)" "$load_before" "$load_after"
