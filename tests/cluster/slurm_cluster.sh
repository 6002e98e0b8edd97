#!/usr/bin/env bash
# A real one-node Slurm cluster runs the atlas job array of docs/cli.md ("sphtroch atlas, atlas-merge").
#
# Usage: slurm_cluster.sh SPHTROCH_EXE WORKDIR
#
# Starts munged (or reuses a running one), slurmctld and slurmd by hand (no systemd) with a
# slurm.conf of its own in a temporary directory, then:
#   1. runs the job script of docs/cli.md as `sbatch --wait --array=1-4` (grid 64, shards I/4) and checks
#      that `atlas-merge` of the four slices is byte-identical to the unsharded `atlas` run;
#   2. runs the array again with task 3 failing before it writes its slice, and checks that
#      `atlas-merge` refuses with exit status 2 and one stderr line naming shard 3/4;
#   3. reruns only that shard (`sbatch --wait --array=3`) and checks the merge again.
# Stops every daemon it started, by pid, and removes its temporary directory on exit.
# Needs root, Debian's slurm-wlm and munge (tests/cluster/install_slurm.sh installs them).
# Exits 0 only if every check passed.
set -euo pipefail

readonly GRID=64 SHARDS=4 FAILED_TASK=3
readonly WAIT_DAEMON=60 WAIT_ARRAY=90 # seconds, upper bounds for each wait
readonly BUDGET=200                    # seconds for all the waits together (ctest's TIMEOUT is 300)

PATH="$PATH:/usr/sbin:/sbin"
tmp="" munged_pid="" slurmctld_pid="" slurmd_pid="" sbatch_pid="" checks=0 rc=0

say() { printf 'cluster: %s\n' "$*"; }
die() {
  printf 'cluster: FAIL: %s\n' "$*" >&2
  exit 1
}
# check DESCRIPTION COMMAND...: runs COMMAND, counts and prints the result; a failure ends the test.
check() {
  local what=$1
  shift
  checks=$((checks + 1))
  if "$@"; then
    say "ok $checks: $what"
  else
    die "check $checks: $what"
  fi
}

# limit SECONDS: SECONDS, or less so that the test stays within its BUDGET (at least 1).
limit() {
  local left=$((BUDGET - SECONDS))
  ((left < 1)) && left=1
  echo $(($1 < left ? $1 : left))
}

# wait_for SECONDS DESCRIPTION COMMAND...: polls COMMAND every 0.5 s until it succeeds.
wait_for() {
  local seconds what=$2 deadline
  seconds=$(limit "$1")
  shift 2
  deadline=$((SECONDS + seconds))
  until "$@" >/dev/null 2>&1; do
    ((SECONDS < deadline)) || return 1
    sleep 0.5
  done
  say "$what (after $((SECONDS - deadline + seconds)) s)"
}

# --- prerequisites --------------------------------------------------------------------------

require_tools() {
  ((EUID == 0)) || die "must run as root (starts slurmctld, slurmd and munged)"
  local cmd missing=()
  for cmd in slurmctld slurmd sbatch sinfo scontrol scancel squeue munged munge unmunge setpriv timeout cmp; do
    command -v "$cmd" >/dev/null 2>&1 || missing+=("$cmd")
  done
  ((${#missing[@]} == 0)) ||
    die "not installed: ${missing[*]} (Debian: slurm-wlm munge; run tests/cluster/install_slurm.sh)"
  [[ -x $exe ]] || die "not an executable: $exe"
}

# --- munge ----------------------------------------------------------------------------------

munge_works() { munge -n </dev/null 2>/dev/null | unmunge >/dev/null 2>&1; }

# Reuses a running munged; otherwise starts one as the munge user in munge's default places
# (/run/munge socket and pid, /var/log/munge), creating a key first if there is none.
start_munge() {
  if munge_works; then
    say "munged already running: reusing it (and leaving it running)"
    return
  fi
  local key=/etc/munge/munge.key
  if [[ ! -s $key ]]; then
    say "no munge key: creating $key"
    install -d -o munge -g munge -m 0700 /etc/munge
    if command -v mungekey >/dev/null; then
      setpriv --reuid=munge --regid=munge --init-groups mungekey --create --keyfile="$key"
    else
      create-munge-key -f
    fi
  fi
  install -d -o munge -g munge -m 0755 /run/munge
  install -d -o munge -g munge -m 0700 /var/log/munge
  install -d -o munge -g munge -m 0711 /var/lib/munge
  setpriv --reuid=munge --regid=munge --init-groups munged --foreground >"$tmp/munged.out" 2>&1 &
  munged_pid=$!
  wait_for 15 "munged started (pid $munged_pid)" munge_works || die "munged did not start: $(cat "$tmp/munged.out")"
}

# --- slurm ----------------------------------------------------------------------------------

port_free() {
  if command -v ss >/dev/null; then
    [[ -z $(ss -Htan "sport = :$1") ]]
  else
    if (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; then return 1; fi # something answers there
  fi
}

# A free TCP port in 20000..29999 (below the ephemeral range), not equal to $1.
free_port() {
  local port _
  for _ in {1..100}; do
    port=$((20000 + RANDOM % 10000))
    [[ $port != "${1:-}" ]] && port_free "$port" && echo "$port" && return
  done
  die "no free port found in 20000..29999"
}

# slurm.conf for a cluster of this one host; everything it writes lives under $tmp.
write_slurm_conf() {
  local host=$1 ctld_port=$2 slurmd_port=$3 cpus mem
  cpus=$(nproc)
  mem=$(free -m | awk '/^Mem:/ {print $2}')
  mem=$((mem * 9 / 10 > mem - 512 ? mem - 512 : mem * 9 / 10)) # slurmd drains a node that has less
  ((mem >= 256)) || mem=256
  mkdir -p "$tmp/state" "$tmp/spool"
  cat >"$SLURM_CONF" <<EOF
# One-node test cluster written by tests/cluster/slurm_cluster.sh
ClusterName=sphtroch-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
  say "slurm.conf: $host, CPUs=$cpus, RealMemory=$mem MB, ports $ctld_port (slurmctld) and $slurmd_port (slurmd)"
}

node_state() { sinfo -h -N -n "$host" -o %t 2>/dev/null; }
node_idle() { [[ $(node_state) == idle ]]; }
ctld_up() { scontrol ping | grep -q 'is UP'; }
no_jobs_left() { [[ -z $(squeue -h) ]]; }

start_slurm() {
  local ctld_port slurmd_port
  ctld_port=$(free_port)
  slurmd_port=$(free_port "$ctld_port")
  write_slurm_conf "$host" "$ctld_port" "$slurmd_port"

  slurmctld -D -f "$SLURM_CONF" >"$tmp/slurmctld.out" 2>&1 &
  slurmctld_pid=$!
  wait_for "$WAIT_DAEMON" "slurmctld answers (pid $slurmctld_pid)" ctld_up || die "slurmctld did not start"

  slurmd -D -f "$SLURM_CONF" -N "$host" >"$tmp/slurmd.out" 2>&1 &
  slurmd_pid=$!
  local deadline=$((SECONDS + $(limit "$WAIT_DAEMON"))) state
  until node_idle; do
    state=$(node_state)
    # A node left down or drained (e.g. by an earlier run's state) is put back into service.
    if [[ $state == down* || $state == drain* ]]; then
      scontrol update nodename="$host" state=resume >/dev/null 2>&1 || true
    fi
    ((SECONDS < deadline)) || die "node $host not idle after $WAIT_DAEMON s (state: ${state:-none})"
    kill -0 "$slurmd_pid" 2>/dev/null || die "slurmd exited"
    sleep 0.5
  done
  say "node $host is idle (slurmd pid $slurmd_pid)"
}

# --- cleanup --------------------------------------------------------------------------------

# stop_pid PID NAME: SIGTERM, up to 10 s for it to exit, then SIGKILL.
stop_pid() {
  local pid=$1 name=$2 _
  [[ -n $pid ]] && kill -0 "$pid" 2>/dev/null || return 0
  kill -TERM "$pid" 2>/dev/null || true
  for _ in {1..20}; do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.5
  done
  kill -0 "$pid" 2>/dev/null && kill -KILL "$pid" 2>/dev/null && say "$name (pid $pid) killed"
  wait "$pid" 2>/dev/null || true
  say "stopped $name (pid $pid)"
}

cleanup() {
  local status=$?
  trap - EXIT INT TERM
  set +e
  stop_pid "$sbatch_pid" "sbatch --wait"
  if [[ -n $slurmctld_pid ]] && kill -0 "$slurmctld_pid" 2>/dev/null; then
    # Jobs of this cluster only (SLURM_CONF points at it): none is left running on slurmd's node.
    scancel --full --quiet --user=root 2>/dev/null
    wait_for 15 "no job left in the cluster" no_jobs_left
  fi
  stop_pid "$slurmd_pid" slurmd
  stop_pid "$slurmctld_pid" slurmctld
  stop_pid "$munged_pid" munged
  if ((status != 0)) && [[ -n $tmp ]]; then
    local log
    for log in "$tmp"/slurmctld.log "$tmp"/slurmd.log "$tmp"/munged.out; do
      [[ -s $log ]] && printf -- '--- last lines of %s\n' "${log##*/}" && tail -n 15 "$log"
    done
  fi
  [[ -n $tmp ]] && rm -rf "$tmp"
  if ((status == 0)); then
    say "all $checks checks passed"
  else
    say "FAILED (exit status $status) after $checks checks"
  fi
  exit "$status"
}

# --- the job array of docs/cli.md -----------------------------------------------------------------

# The job script: docs/cli.md's atlas.sbatch with a small grid, 4 shards and $exe for `sphtroch`,
# taken from docs/cli.md when it is beside the tests (so the test follows the documented text).
# Task $SPHTROCH_FAIL_TASK, when that is set, fails (exit 42) before it writes anything.
write_job_script() {
  local readme=$source_dir/docs/cli.md body qexe
  printf -v qexe '%q' "$exe"
  [[ -r $readme ]] || die "no docs/cli.md at $readme"
  body=$(sed -n '/^# atlas\.sbatch — /,/^# afterwards, once:/p' "$readme" | sed '$d')
  [[ -n $body ]] || die "docs/cli.md has no '# atlas.sbatch — ' block"
  body=$(sed -e "s|--array=1-16|--array=1-$SHARDS|" -e "s|--grid 4096|--grid $GRID|" \
    -e "s|/16\"|/$SHARDS\"|" -e "s|^sphtroch |$qexe |" <<<"$body")
  [[ $body == *"$qexe atlas --n 2 --grid $GRID "* && $body == *"/$SHARDS\" -o \"slice-\$SLURM_ARRAY_TASK_ID.csv\""* ]] ||
    die "docs/cli.md's atlas.sbatch block changed; adapt write_job_script: $body"
  cat >"$work/atlas.sbatch" <<EOF
#!/bin/sh
#SBATCH --job-name=sphtroch-atlas
#SBATCH --cpus-per-task=1
#SBATCH --output=slurm-%A_%a.out
# tests/cluster: task \$SPHTROCH_FAIL_TASK fails on purpose, before it writes its slice.
if [ "\${SPHTROCH_FAIL_TASK:-0}" = "\$SLURM_ARRAY_TASK_ID" ]; then
  echo "task \$SLURM_ARRAY_TASK_ID fails on purpose" >&2
  exit 42
fi
$body
EOF
  say "job script $work/atlas.sbatch:"
  sed 's/^/    /' "$work/atlas.sbatch"
}

# run_array DIR ARRAY [FAIL_TASK]: sbatch --wait the job script in DIR; sets rc to sbatch's status.
# sbatch runs in the background so that a SIGTERM to this script is handled at once.
run_array() {
  local dir=$1 array=$2 fail=${3:-} seconds start=$SECONDS
  seconds=$(limit "$WAIT_ARRAY")
  mkdir -p "$dir"
  SPHTROCH_FAIL_TASK=$fail timeout "$seconds" \
    sbatch --wait --quiet --array="$array" --chdir="$dir" "$work/atlas.sbatch" &
  sbatch_pid=$!
  rc=0
  wait "$sbatch_pid" || rc=$?
  sbatch_pid=""
  ((rc != 124)) || die "sbatch --array=$array did not finish within $seconds s"
  say "sbatch --wait --array=$array${fail:+ (task $fail fails)} in ${dir##*/}: exit $rc after $((SECONDS - start)) s"
}

# merge DIR: docs/cli.md's `atlas-merge -o atlas.csv --svg atlas.svg slice-*.csv` in DIR, writing
# merged.csv and merged.svg; its stderr goes to DIR/merge.err (and is shown), rc is its exit status.
merge() {
  rc=0
  (cd "$1" && "$exe" atlas-merge -o merged.csv --svg merged.svg slice-*.csv >/dev/null 2>merge.err) || rc=$?
  say "atlas-merge in ${1##*/}: exit $rc"
  [[ ! -s $1/merge.err ]] || sed 's/^/    stderr: /' "$1/merge.err"
}

slices_written() { # DIR N...: exactly slice-N.csv for the given N exist
  local dir=$1 n want=() have
  shift
  for n in "$@"; do want+=("slice-$n.csv"); done
  have=$(cd "$dir" && shopt -s nullglob && printf '%s\n' slice-*.csv | sort | tr '\n' ' ')
  [[ $have == "$(printf '%s\n' "${want[@]}" | sort | tr '\n' ' ')" ]]
}
one_line_naming_missing_shard() { # FILE: one line, naming shard 3/4 as missing
  [[ $(wc -l <"$1") -eq 1 ]] && grep -q "shard $FAILED_TASK/$SHARDS missing" "$1"
}
threads_from_slurm() { # DIR: all $SHARDS tasks' summaries say they ran on $SLURM_CPUS_PER_TASK = 1 thread
  [[ $(grep -l 'on 1 thread(s)' "$1"/slurm-*_*.out 2>/dev/null | wc -l) -eq $SHARDS ]]
}

# --- main -----------------------------------------------------------------------------------

(($# == 2)) || die "usage: slurm_cluster.sh SPHTROCH_EXE WORKDIR"
exe=$(realpath "$1")
work=$2
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
host=$(hostname -s)
require_tools

trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
tmp=$(mktemp -d /tmp/sphtroch-slurm.XXXXXX)
export SLURM_CONF=$tmp/slurm.conf
mkdir -p "$work"
work=$(cd "$work" && pwd)
rm -rf "$work/whole" "$work/array" "$work/broken" "$work/atlas.sbatch"

say "sphtroch: $exe; work directory: $work; temporary directory: $tmp"
start_munge
start_slurm
write_job_script

# The reference: the unsharded atlas, computed outside the cluster.
mkdir -p "$work/whole"
(cd "$work/whole" && "$exe" atlas --n 2 --grid "$GRID" -o whole.csv --svg whole.svg >/dev/null 2>&1) ||
  die "sphtroch atlas --n 2 --grid $GRID failed"
whole=$work/whole/whole.csv

say "step 1: the whole job array"
run_array "$work/array" "1-$SHARDS"
check "sbatch --wait --array=1-$SHARDS exits 0" test "$rc" = 0
check "every task wrote its slice: slice-1..$SHARDS.csv" slices_written "$work/array" 1 2 3 4
check "every task ran --threads \"\$SLURM_CPUS_PER_TASK\" = 1 thread" threads_from_slurm "$work/array"
merge "$work/array"
check "atlas-merge of the $SHARDS slices exits 0" test "$rc" = 0
check "merged.csv is byte-identical to the unsharded whole.csv" cmp "$work/array/merged.csv" "$whole"
check "merged.svg is byte-identical to the unsharded whole.svg" cmp "$work/array/merged.svg" "$work/whole/whole.svg"

say "step 2: the job array with task $FAILED_TASK failing before it writes its slice"
run_array "$work/broken" "1-$SHARDS" "$FAILED_TASK"
check "sbatch --wait reports the failed task's exit status 42" test "$rc" = 42
check "tasks 1, 2, 4 wrote their slices, task $FAILED_TASK none" slices_written "$work/broken" 1 2 4
merge "$work/broken"
check "atlas-merge refuses the incomplete set with exit status 2" test "$rc" = 2
check "atlas-merge's stderr is one line naming shard $FAILED_TASK/$SHARDS as missing" \
  one_line_naming_missing_shard "$work/broken/merge.err"
check "atlas-merge left no merged.csv" test ! -e "$work/broken/merged.csv"

say "step 3: rerun only task $FAILED_TASK, then merge again"
run_array "$work/broken" "$FAILED_TASK"
check "sbatch --wait --array=$FAILED_TASK exits 0" test "$rc" = 0
check "slice-$FAILED_TASK.csv now written" slices_written "$work/broken" 1 2 3 4
merge "$work/broken"
check "atlas-merge of the completed set exits 0" test "$rc" = 0
check "merged.csv is byte-identical to the unsharded whole.csv" cmp "$work/broken/merged.csv" "$whole"
