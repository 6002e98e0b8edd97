#!/usr/bin/env bash
# ctest bench:median_time — bench/median_time.sh against commands whose times, memory and exit
# statuses are known beforehand: runs that sleep 0.2, 0.6 and 1.0 s in turn (median 0.6 s plus
# the start of a process, under 1.0 s), two runs of 0.2 and 0.6 s (median: their mean), a process
# that holds 64 MiB, exit statuses 3 and 0/1; and bad arguments (exit 2, one line on stderr,
# nothing on stdout). Everything it writes stays in a temporary directory.
#
#   bash tests/bench/median_time_test.sh [REPO_ROOT]
set -uo pipefail
root=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
script=$root/bench/median_time.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "median_time_test: $*"; failures=$((failures + 1)); }

# seconds FIELD LINE: the value after the first word FIELD ("median", "min", "max") of the line, in seconds.
seconds() { awk -v f="$1" '{for (i = 1; i + 2 <= NF; i++) if ($i == f) {v = $(i + 1); u = $(i + 2); break}} END {gsub(/[,;]/, "", u); print (u == "ms") ? v / 1000 : v}' <<<"$2"; }
# between X LO HI: LO <= X < HI.
between() { awk -v x="$1" -v lo="$2" -v hi="$3" 'BEGIN {exit !(x >= lo && x < hi)}'; }

# A command that sleeps the next of its durations at each run (a counter in the work directory).
cat >"$work/sleeper.sh" <<'EOF'
#!/usr/bin/env bash
dir=$(dirname "$0"); n=$(cat "$dir/count" 2>/dev/null || echo 0); echo $((n + 1)) >"$dir/count"
read -r -a durations <<<"$DURATIONS"; sleep "${durations[n]}"; exit "${STATUSES:-0}"
EOF
chmod +x "$work/sleeper.sh"

line=$(DURATIONS="0.2 0.6 1.0" bash "$script" -n 3 -- "$work/sleeper.sh")
median=$(seconds median "$line")
between "$median" 0.6 1.0 || fail "sleeps of 0.2, 0.6, 1.0 s: median $median s, expected in [0.6, 1.0): $line"
between "$(seconds min "$line")" 0.2 0.6 || fail "sleeps of 0.2, 0.6, 1.0 s: min not in [0.2, 0.6): $line"
between "$(seconds max "$line")" 1.0 2.0 || fail "sleeps of 0.2, 0.6, 1.0 s: max not in [1.0, 2.0): $line"
[[ $line == *"exit 0; 3 runs;"* ]] || fail "three runs of exit 0 not said so: $line"

rm -f "$work/count"
line=$(DURATIONS="0.2 0.6" bash "$script" -n 2 -- "$work/sleeper.sh")
between "$(seconds median "$line")" 0.4 0.6 || fail "sleeps of 0.2 and 0.6 s: median not their mean, in [0.4, 0.6): $line"

line=$(bash "$script" -n 1 -- python3 -c "b = bytearray(64 * 2**20); b[::4096] = b'x' * len(b[::4096])")
rss=$(sed -E 's/.*peak RSS median ([0-9.]+) MiB.*/\1/' <<<"$line")
between "$rss" 64 200 || fail "a process holding 64 MiB: peak RSS $rss MiB, expected in [64, 200): $line"

line=$(bash "$script" -n 2 -- bash -c 'exit 3')
[[ $line == *"exit 3;"* ]] || fail "a command that exits 3: $line"
rm -f "$work/count"
cat >"$work/flip.sh" <<'EOF'
#!/usr/bin/env bash
dir=$(dirname "$0"); n=$(cat "$dir/count" 2>/dev/null || echo 0); echo $((n + 1)) >"$dir/count"; exit $((n % 2))
EOF
chmod +x "$work/flip.sh"
line=$(bash "$script" -n 2 -- "$work/flip.sh")
[[ $line == *"exit 0/1;"* ]] || fail "runs that exit 0 then 1: $line"

for args in "" "-x 3 -- true" "-n" "-n 0 -- true" "-n 1001 -- true" "-n 2x -- true" "-n 3" "-n 3 true" "-n 3 --" \
  "-n 3 -- no-such-command-here" "-n 3 -- $work"; do
  # shellcheck disable=SC2086
  bash "$script" $args >"$work/out" 2>"$work/err"
  status=$?
  [[ $status -eq 2 && ! -s $work/out && $(wc -l <"$work/err") -eq 1 ]] ||
    fail "arguments '$args': exit $status, $(wc -c <"$work/out") bytes on stdout, $(wc -l <"$work/err") lines on stderr; expected 2, 0, 1"
done

if ((failures)); then
  echo "median_time_test: $failures failure(s)"
  exit 1
fi
echo "median_time_test: medians, range, peak RSS, exit statuses and bad arguments as expected"
