#!/usr/bin/env bash
# Runs every libFuzzer target (fuzz/CMakeLists.txt) for SECONDS each, at the
# lowest CPU priority, and adds up executions over all runs so far.
#
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]      (default 60 s, every target)
#
# Builds the `fuzz` preset (clang 14, -fsanitize=fuzzer,address,undefined)
# into build-fuzz/ first. Each target starts from its committed seeds
# (fuzz/corpus/<target>, read only) plus what earlier runs found
# (build-fuzz/corpus/<target>, kept between runs). A crash, leak, timeout or
# failed check is written to build-fuzz/artifacts/<target>/ and the script
# exits 1; commit such an input under fuzz/regressions/<target>/ with its
# fix (ctest fuzz_replay_<target> replays it). Executions per run are
# appended to build-fuzz/fuzz_runs.tsv; the totals are printed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."

SECONDS_PER_TARGET="${1:-60}"
shift || true
if ! [[ "$SECONDS_PER_TARGET" =~ ^[0-9]+$ ]] || [ "$SECONDS_PER_TARGET" -le 0 ]; then
  echo "fuzz.sh: SECONDS must be a positive integer, got \"$SECONDS_PER_TARGET\"" >&2
  exit 2
fi
command -v clang++-14 >/dev/null || { echo "fuzz.sh: clang++-14 missing (bash scripts/setup.sh)" >&2; exit 2; }

launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
if [ ! -f build-fuzz/build.ninja ]; then cmake --preset fuzz "${launcher[@]}" >/dev/null; fi
nice cmake --build build-fuzz --target fuzzers -j "${FUZZ_BUILD_JOBS:-2}"

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=($(sed -n '/^set(MESHSEG_FUZZ_TARGETS/,/)/p' fuzz/CMakeLists.txt \
    | sed 's/set(MESHSEG_FUZZ_TARGETS//; s/)//'))
fi

# The volume and sniffed-format targets write each input to a scratch file
# under $TMPDIR (the readers take a path); on a disk-backed /tmp that write
# dominates an execution, so use memory-backed /dev/shm where there is one
# (about 7x the executions per second). FUZZ_TMPDIR overrides it.
scratch="${FUZZ_TMPDIR:-}"
if [ -z "$scratch" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then scratch=/dev/shm; fi
if [ -n "$scratch" ]; then export TMPDIR="$scratch"; fi

log=build-fuzz/fuzz_runs.tsv
[ -f "$log" ] || printf 'date\ttarget\tseconds\texecutions\tfindings\n' > "$log"
found=0
for t in "${targets[@]}"; do
  bin="build-fuzz/bin/fuzz_$t"
  [ -x "$bin" ] || { echo "fuzz.sh: no target $t ($bin)" >&2; exit 2; }
  mkdir -p "build-fuzz/corpus/$t" "build-fuzz/artifacts/$t"
  out="build-fuzz/artifacts/$t/last_run.log"
  before=$(find "build-fuzz/artifacts/$t" -type f ! -name '*.log' | wc -l)
  # -max_len 8 KiB: long enough for several elements of every format, short
  # enough to keep executions fast; -timeout 10 s flags a reader stuck on
  # input it should refuse; -rss_limit_mb flags one that allocates from a
  # declared count instead of the bytes present.
  set +e
  nice -n 19 "$bin" -max_total_time="$SECONDS_PER_TARGET" -max_len=8192 -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t/" \
    "build-fuzz/corpus/$t" "fuzz/corpus/$t" > "$out" 2>&1
  rc=$?
  set -e
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out" | tail -1)
  after=$(find "build-fuzz/artifacts/$t" -type f ! -name '*.log' | wc -l)
  findings=$((after - before))
  printf '%s\t%s\t%s\t%s\t%s\n' "$(date -u +%FT%TZ)" "$t" "$SECONDS_PER_TARGET" "${execs:-0}" \
    "$findings" >> "$log"
  echo "fuzz $t: ${execs:-0} executions in ${SECONDS_PER_TARGET} s, $findings new findings (exit $rc)"
  if [ "$rc" -ne 0 ] || [ "$findings" -gt 0 ]; then
    found=1
    grep -m3 -E 'ERROR|fuzz check failed|runtime error|Test unit written' "$out" || true
  fi
done

echo "--- executions over all runs (build-fuzz/fuzz_runs.tsv)"
awk -F'\t' 'NR > 1 { e[$2] += $4; f[$2] += $5; s[$2] += $3 }
  END { for (t in e) printf "%-14s %12d executions %8d s %3d findings\n", t, e[t], s[t], f[t] }' \
  "$log" | sort
exit "$found"
