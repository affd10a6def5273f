#!/usr/bin/env bash
# Issue 29 benchmark: the cost of the Redis mode and how it scales, with real
# processes on loopback (a redis-server with AOF on, meshseg-server replicas).
#   1. small jobs (--small-part, ~0.1 s of work each): jobs/s and latency,
#      embedded (1 process) vs Redis mode (1 api + worker processes), with 1
#      and 2 workers. One client running jobs back to back gives the per-job
#      latency; Redis mean minus embedded mean is the per-job overhead.
#   2. long jobs (test_piece, >= 1 s each) with every worker process pinned
#      to its own core (taskset): jobs/s of 2 workers over 1 worker.
# Usage (after building meshseg-server and service_load_bench):
#   bash bench/service/scale_out.sh [SMALL_JOBS=40] [LONG_JOBS=6]
#   SMALL_VOXEL=3 bash bench/service/scale_out.sh 100 0   # tiny jobs: overhead only
# Prints the load average (uptime) before each run: other builds on the
# machine distort the numbers, so compare runs made at similar load.
set -euo pipefail
cd "$(dirname "$0")/../.."
BIN=build/bin
SMALL_JOBS="${1:-40}"
LONG_JOBS="${2:-6}"
SMALL_PART="${SMALL_PART:-small_block}"
SMALL_VOXEL="${SMALL_VOXEL:-0}"
LONG_PART="${LONG_PART:-test_piece}"
LONG_VOXEL="${LONG_VOXEL:-0.5}"
WORK=$(mktemp -d /tmp/meshseg-scale-out.XXXXXX)
PIDS=()

cleanup() {
  for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$WORK"
}
trap cleanup EXIT

free_port() {
  python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'
}

# start_server NAME [taskset CPU|-] FLAGS...: starts meshseg-server, sets ADDR.
start_server() {
  local name=$1 cpus=$2
  shift 2
  local pin=()
  [ "$cpus" != "-" ] && pin=(taskset -c "$cpus")
  mkdir -p "$WORK/$name"
  "${pin[@]}" "$BIN/meshseg-server" --listen 127.0.0.1:0 --spool-dir "$WORK/$name/spool" "$@" \
    >"$WORK/$name/out" 2>"$WORK/$name/log" &
  PIDS+=($!)
  ADDR=""
  for _ in $(seq 1 200); do
    ADDR=$(sed -n 's/^listening on //p' "$WORK/$name/out")
    [ -n "$ADDR" ] && return 0
    sleep 0.05
  done
  echo "scale_out: $name did not start" >&2
  cat "$WORK/$name/log" >&2
  exit 1
}

start_redis() {
  REDIS_PORT=$(free_port)
  mkdir -p "$WORK/redis"
  redis-server --port "$REDIS_PORT" --bind 127.0.0.1 --dir "$WORK/redis" --appendonly yes \
    --save '' --daemonize no --logfile "$WORK/redis/log" &
  PIDS+=($!)
  for _ in $(seq 1 200); do
    redis-cli -p "$REDIS_PORT" ping >/dev/null 2>&1 && return 0
    sleep 0.05
  done
  echo "scale_out: redis-server did not start" >&2
  exit 1
}

stop_all() {
  for pid in "${PIDS[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  PIDS=()
  rm -rf "${WORK:?}"/*
}

load() { echo "   load: $(uptime | sed 's/.*load average: //')"; }

run() {  # LABEL SERVERS CLIENTS JOBS PART VOXEL
  load
  "$BIN/service_load_bench" --label="$1" --servers="$2" --clients="$3" --jobs="$4" \
    --part="$5" --voxel="$6" --work_dir="$WORK"
}

# redis_setup WORKERS [CPU per worker...]: 1 api + WORKERS worker processes.
redis_setup() {
  local n=$1
  shift
  start_redis
  local common=(--queue "redis://127.0.0.1:$REDIS_PORT" --blob-dir "$WORK/blobs")
  start_server api - --role api "${common[@]}"
  API=$ADDR
  for i in $(seq 1 "$n"); do
    local cpu="${1:--}"
    [ $# -gt 0 ] && shift
    start_server "worker$i" "$cpu" --role worker --workers 1 "${common[@]}"
  done
}

echo "== small jobs ($SMALL_PART, $SMALL_JOBS per run)"
start_server embedded1 - --workers 1
run "embedded w=1 c=1" "$ADDR" 1 "$SMALL_JOBS" "$SMALL_PART" "$SMALL_VOXEL"
run "embedded w=1 c=4" "$ADDR" 4 $((SMALL_JOBS / 4)) "$SMALL_PART" "$SMALL_VOXEL"
stop_all
start_server embedded2 - --workers 2
run "embedded w=2 c=4" "$ADDR" 4 $((SMALL_JOBS / 4)) "$SMALL_PART" "$SMALL_VOXEL"
stop_all
redis_setup 1
redis-cli -p "$REDIS_PORT" config resetstat >/dev/null
run "redis api+1 worker c=1" "$API" 1 "$SMALL_JOBS" "$SMALL_PART" "$SMALL_VOXEL"
# What Redis itself did for those jobs: commands per job and their time
# inside Redis (idle XREADGROUP waits of 1 s excluded: they block, not work).
redis-cli -p "$REDIS_PORT" info commandstats | tr -d '\r' | awk -F'[:,=]' -v jobs="$SMALL_JOBS" '
  /^cmdstat_/ { name = substr($1, 9); calls[name] = $3; usec[name] = $5 }
  END {
    for (n in calls) { if (n != "xreadgroup") { c += calls[n]; u += usec[n] } }
    printf "   redis per job: %.1f commands, %.3f ms inside redis (+%.1f XREADGROUP)\n",
           c / jobs, u / jobs / 1000, calls["xreadgroup"] / jobs
  }'
run "redis api+1 worker c=4" "$API" 4 $((SMALL_JOBS / 4)) "$SMALL_PART" "$SMALL_VOXEL"
stop_all
redis_setup 2
run "redis api+2 workers c=4" "$API" 4 $((SMALL_JOBS / 4)) "$SMALL_PART" "$SMALL_VOXEL"
stop_all

[ "$LONG_JOBS" -gt 0 ] || exit 0
echo "== long jobs ($LONG_PART h=$LONG_VOXEL, each worker pinned to one core)"
redis_setup 1 0
run "redis 1 worker@cpu0 c=2" "$API" 2 $((LONG_JOBS / 2)) "$LONG_PART" "$LONG_VOXEL"
stop_all
redis_setup 2 0 1
run "redis 2 workers@cpu0,1 c=4" "$API" 4 $((LONG_JOBS / 2)) "$LONG_PART" "$LONG_VOXEL"
stop_all
