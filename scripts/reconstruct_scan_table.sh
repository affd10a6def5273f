#!/bin/bash
# Issue 38's table of generated occluded scans: the 12 scans (ScanPart through
# `meshseg generate PART --scan`, 4 views from 35° above, so undersides are
# unseen) reconstructed at each covering seed, one row per (scan, seed):
# accuracy p95 and visible completeness p95 in sp (reconstruct_eval), the
# bars (≤ 3.5 and ≤ 5.5 at once), topology, and genus before and after the
# support step (reconstruct_timing).
#   scripts/reconstruct_scan_table.sh BIN_DIR WORK_DIR OUT_FILE ["SEEDS"] [SCAN ...]
# BIN_DIR holds meshseg, reconstruct_timing and reconstruct_eval (copy them
# if the build may change while this runs). Scans and truths are made once
# in WORK_DIR. SEEDS defaults to "0 1 2 3"; SCANs to all 12. Every run is
# niced and limited to 300 s.
set -u
B=$1; D=$2; OUT=$3; SEEDS=${4:-0 1 2 3}; shift $(( $# < 4 ? $# : 4 ))
mkdir -p "$D"
# name part points generator-seed
LIST="tp60 test_piece 60000 1
tp40 test_piece 40000 1
tp40s2 test_piece 40000 2
tp15 test_piece 15000 1
ss40 stepped_shaft 40000 1
ss15 stepped_shaft 15000 1
rounded_prism rounded_prism 15000 1
bbs2 blend_block 15000 2
torus_ring torus_ring 15000 1
blend_block blend_block 15000 1
small_block small_block 15000 1
plate_boss plate_boss 15000 1"
NAMES=${*:-$(echo "$LIST" | awk '{print $1}')}
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
for name in $NAMES; do
  read -r _ part n gseed <<< "$(echo "$LIST" | awk -v n="$name" '$1 == n')"
  [ -n "$part" ] || { echo "unknown scan $name" >&2; exit 1; }
  [ -f "$D/$name.xyz" ] || nice "$B/meshseg" generate "$part" --scan "$D/$name.xyz" \
      --scan-points "$n" --seed "$gseed" > /dev/null
  [ -f "$D/${part}_truth.ply" ] || nice "$B/meshseg" generate "$part" -o "$D/${part}_truth.ply" > /dev/null
  for s in $SEEDS; do
    if ! nice timeout 300 "$B/reconstruct_timing" "$D/$name.xyz" "$W/out.ply" "seed=$s" > "$W/t.txt" 2>&1; then
      echo "$name s$s FAILED" >> "$OUT"; continue
    fi
    nice timeout 300 "$B/reconstruct_eval" "$W/out.ply" "$D/${part}_truth.ply" "$D/$name.xyz" > "$W/e.txt" 2>&1
    acc=$(awk '/^accuracy/{print $5}' "$W/e.txt")
    vis=$(awk '/^visible compl/{print $6}' "$W/e.txt")
    topo=$(grep -o 'open edges [0-9]*, non-manifold edges [0-9]*, non-manifold vertices [0-9]*, degenerate faces [0-9]*, components [0-9]*, genus [0-9]* (truth [0-9]*)' "$W/e.txt")
    support=$(grep -o 'genus [0-9-]* -> [0-9-]*' "$W/t.txt")
    ok=no; awk -v a="$acc" -v v="$vis" 'BEGIN{exit !(a <= 3.5 && v <= 5.5)}' && ok=yes
    printf "%-13s s%s acc %5s vis %5s bars %-3s | %s | support %s\n" "$name" "$s" "$acc" "$vis" "$ok" "$topo" "$support" >> "$OUT"
  done
done
