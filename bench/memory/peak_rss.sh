#!/bin/bash
# Measures the peak resident memory of `meshseg segment` per input kind and
# size, next to the admission model's estimate (`meshseg info
# --memory-estimate`), for core/src/pipeline/memory_model.h. Not run by ctest:
# it takes minutes. Usage: bash bench/memory/peak_rss.sh [BUILD_DIR] [OUT_DIR]
# Prints one line per input: kind, elements, peak RSS, estimate, ratio.
set -euo pipefail
BIN=${1:-build}/bin
OUT=${2:-$(mktemp -d)}
DATA=$(cd "$(dirname "$0")/../../../shared/data" && pwd)
M="$BIN/meshseg"
mkdir -p "$OUT"

measure() {  # kind file elements
  local kind=$1 file=$2 n=$3
  /usr/bin/time -v -o "$file.time" nice "$M" segment "$file" -o "$file.json" >/dev/null 2>&1
  local rss_kib est
  rss_kib=$(awk '/Maximum resident/ {print $NF}' "$file.time")
  est=$("$M" info "$file" --memory-estimate | sed 's/.*"peak_bytes": \([0-9]*\).*/\1/')
  awk -v k="$kind" -v f="$(basename "$file")" -v n="$n" -v r="$rss_kib" -v e="$est" 'BEGIN {
    printf "%-6s %-28s %9d elements  peak %7.1f MiB  estimate %7.1f MiB  estimate/peak %.2f\n",
           k, f, n, r / 1024, e / 1048576, e / (r * 1024) }'
}

# Scan-like meshes: the generated CT-like part at four voxel sizes.
for h in 1.0 0.7 0.5 0.35; do
  f="$OUT/test_piece_$h.ply"
  faces=$("$M" generate test_piece -o "$f" --voxel-size "$h" | sed 's/.*, \([0-9]*\) faces.*/\1/')
  measure mesh "$f" "$faces"
done
# Point clouds: the same parts' vertices as XYZ.
for h in 1.0 0.7 0.5; do
  "$M" convert "$OUT/test_piece_$h.ply" "$OUT/test_piece_$h.off" >/dev/null
  awk 'NR==2 {nv=$1} NR>2 && NR<=2+nv {print $1, $2, $3}' "$OUT/test_piece_$h.off" \
    > "$OUT/cloud_$h.xyz"
  measure cloud "$OUT/cloud_$h.xyz" "$(wc -l < "$OUT/cloud_$h.xyz")"
done
# A CAD tessellation segmented on a remesh (1 252 faces -> ~136 k).
cp "$DATA/plate_holes.stl" "$OUT/"
measure cad "$OUT/plate_holes.stl" 1252
