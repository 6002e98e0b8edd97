#!/usr/bin/env bash
# Builds the libFuzzer targets (clang-14, ASan + UBSan) and runs each for a bounded time.
#
#   bash tests/fuzz/run.sh [SECONDS_PER_TARGET] [TARGET...]     (default: 10 s, every target)
#
# Budget: CI (.ci/run) runs every target for the default 10 s: 8 targets x 10 s = 80 s of
# fuzzing, the fuzz stage's share of CI's 40 minutes beside its build. A new target must keep
# targets x seconds at or below 80 s (lower the default rather than exceed it); longer runs are
# for changes to a reader (below). The build comes on top:
# fuzz_synth_merge compiles the CGAL synth commands (measured: about 6 minutes of one core).
#
# Each target starts from a scratch copy of tests/fuzz/corpus/TARGET (the checked-in seeds are
# never modified) and runs with -max_total_time=SECONDS, a 10 s per-input timeout and a 2 GiB
# RSS limit. Exits 0 only if no target found a crash, a leak, undefined behaviour, a broken
# invariant (FUZZ_CHECK), a slow input or an out-of-memory input; a finding is saved as
# build-fuzz/artifacts/TARGET/crash-* (or leak-*, timeout-*, oom-*) and its stack printed.
# Reproduce one: build-fuzz/bin/TARGET build-fuzz/artifacts/TARGET/crash-...
# Longer runs: bash tests/fuzz/run.sh 3600 fuzz_scene
#
# Installs clang-14 and its runtime (libclang-rt-14-dev) when missing; the library's own
# dependencies come from scripts/dev.sh. Environment: BUILD_DIR (default build-fuzz).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$root"
seconds=${1:-10}
shift || true
[[ $seconds =~ ^[1-9][0-9]*$ ]] || {
  echo "run.sh: SECONDS_PER_TARGET = '$seconds': expected a whole number >= 1" >&2
  exit 2
}
all_targets=(fuzz_parse fuzz_polyline_input fuzz_atlas_csv fuzz_scene fuzz_cli_values fuzz_timed_polyline
             fuzz_synth_merge fuzz_text_readers)
targets=("$@")
((${#targets[@]})) || targets=("${all_targets[@]}")
build_dir=${BUILD_DIR:-build-fuzz}

packages=(clang-14 libclang-rt-14-dev)
missing=()
for pkg in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done
if ((${#missing[@]})); then
  echo "fuzz: installing ${missing[*]}"
  sudo=()
  ((EUID == 0)) || sudo=(sudo)
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S tests/fuzz -B "$build_dir" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=None >/dev/null
cmake --build "$build_dir" -j "$(nproc)" --target "${targets[@]}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
work=$(mktemp -d "${TMPDIR:-/tmp}/sphtroch-fuzz.XXXXXX")
trap 'rm -rf "$work"' EXIT
failed=()
for target in "${targets[@]}"; do
  [[ -d tests/fuzz/corpus/$target ]] || {
    echo "fuzz: unknown target '$target'; targets: ${all_targets[*]}" >&2
    exit 2
  }
  corpus=$work/$target
  artifacts=$root/$build_dir/artifacts/$target
  mkdir -p "$corpus" "$artifacts"
  cp tests/fuzz/corpus/"$target"/* "$corpus"/
  echo "fuzz: $target for $seconds s"
  # TMPDIR: the targets' scratch files (fuzz_files.hpp) go under $work, removed below even after a crash.
  if TMPDIR="$work" "$build_dir/bin/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" \
      >"$work/$target.log" 2>&1; then
    echo "fuzz: $target ok: $(grep -E '^stat::number_of_executed_units' "$work/$target.log" | awk '{print $2}') inputs," \
         "$(ls "$corpus" | wc -l) in the corpus"
  else
    failed+=("$target")
    echo "fuzz: $target FAILED; the end of its log:" >&2
    tail -n 60 "$work/$target.log" >&2
  fi
done
if ((${#failed[@]})); then
  echo "fuzz: failed: ${failed[*]} (artifacts under $build_dir/artifacts)" >&2
  exit 1
fi
echo "fuzz: every target ran $seconds s without a finding"
