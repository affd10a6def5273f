#!/usr/bin/env bash
# End-to-end volume benchmark (issue #33): a 512^3 uint16 CT volume of the
# test piece -> `meshseg segment` -> regions, with wall time and peak RSS
# from /usr/bin/time -v and the machine's load alongside.
# Usage: bench/voxel/run_volume_bench.sh [BUILD_DIR] [SIZE]
set -euo pipefail
build=${1:-build}
size=${2:-512}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$build/bin/voxel_volume_bench" "$dir/volume.nrrd" test_piece --size "$size" --voxel-size 0.2
echo "load before: $(uptime)"
/usr/bin/time -v "$build/bin/meshseg" segment "$dir/volume.nrrd" -o "$dir/result.json" \
  > "$dir/segment.out" 2> "$dir/time.txt" || { cat "$dir/time.txt"; exit 1; }
echo "load after:  $(uptime)"
head -3 "$dir/segment.out"
grep -c '"id"' "$dir/result.json" | sed 's/^/result ids (regions, curves, ...): /'
grep -E "Elapsed \(wall|Maximum resident|User time|System time" "$dir/time.txt"
