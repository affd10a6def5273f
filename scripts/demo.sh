#!/usr/bin/env bash
# The main job on the embedded default: installs, builds, generates a CT-like
# part, starts meshseg-server on localhost, segments the part through the
# client, prints a summary, writes the result, stops the server.
set -euo pipefail
cd "$(dirname "$0")/.."

PART="${MESHSEG_DEMO_PART:-test_piece}"
OUT="out/demo"

bash scripts/setup.sh
cmake --preset default >/dev/null
cmake --build --preset default --target meshseg meshseg-server

mkdir -p "$OUT"
BIN=build/bin
echo "== generating CT-like part '$PART'"
"$BIN/meshseg" generate "$PART" -o "$OUT/$PART.ply" --ground-truth "$OUT/$PART.truth.json"
"$BIN/meshseg" info "$OUT/$PART.ply"

echo "== starting meshseg-server on 127.0.0.1 (ephemeral port)"
LOG="$OUT/server.log"
"$BIN/meshseg-server" --listen 127.0.0.1:0 --spool-dir "$OUT/spool" >"$LOG" 2>&1 &
SERVER_PID=$!
trap 'kill -TERM $SERVER_PID 2>/dev/null || true; wait $SERVER_PID 2>/dev/null || true' EXIT

ADDR=""
for _ in $(seq 1 100); do
  ADDR=$(grep -Eo 'listening on [0-9.]+:[0-9]+' "$LOG" | head -n 1 | awk '{print $3}') || true
  [ -n "$ADDR" ] && break
  kill -0 "$SERVER_PID" 2>/dev/null || { cat "$LOG" >&2; echo "demo: server exited early" >&2; exit 1; }
  sleep 0.1
done
[ -n "$ADDR" ] || { cat "$LOG" >&2; echo "demo: server did not report its address" >&2; exit 1; }
echo "   server at $ADDR"

echo "== segmenting through the server"
"$BIN/meshseg" segment "$OUT/$PART.ply" --server "$ADDR" \
  -o "$OUT/$PART.result.json" --colored-ply "$OUT/$PART.segments.ply"

echo "== stopping the server"
kill -TERM "$SERVER_PID"
wait "$SERVER_PID" || true
trap - EXIT
echo "wrote $OUT/$PART.result.json and $OUT/$PART.segments.ply (colour per region)"
