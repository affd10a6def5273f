#!/usr/bin/env bash
# Times the exact-facet path (exact_path_bench) on every labelled CAD mesh of
# ../shared/data (cad/ gmsh and CAD-export tessellations, abc_00007974_5):
# one row per file (facets, regions, wall seconds of read + exactness estimate
# + segmentation, the segmentation's wall and CPU seconds, peak MiB, CPU
# seconds of read + exactness estimate + segmentation), and each
# file's region table in OUT_DIR (diff two OUT_DIRs to compare
# the regions of two builds).
# usage: bench/cad/exact_path_files.sh [BENCH] [OUT_DIR] [RUNS]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
bench="${1:-$here/../../build/bin/exact_path_bench}"
out="${2:-/tmp/exact_path_files}"
runs="${3:-1}"
data="$here/../../../shared/data"
mkdir -p "$out"
printf '%-70s %8s %7s %8s %9s %8s %8s %11s\n' file facets regions total_s segment_s cpu_s peak_MiB total_cpu_s
for mesh in "$data"/cad/*.obj "$data/abc_00007974_5.obj"; do
  name="$(basename "$mesh")"
  if ! timeout 600 "$bench" "$mesh" "$runs" "$out/$name.regions" >"$out/$name.log" 2>&1; then
    echo "$name: FAILED $(tail -1 "$out/$name.log")"
    continue
  fi
  awk -v name="$name" '
    /^(read|exactness)/ { total += $2; total_cpu += $5 }
    /^mesh/ { facets = $4 }
    /^segment/ { wall = $2; total += $2; cpu = $5; peak = $9; total_cpu += $5 }
    /^regions/ { regions = $2 + 0 }
    END { printf "%-70s %8s %7s %8.3f %9s %8s %8s %11.3f\n", name, facets, regions, total, wall, cpu, peak, total_cpu }' \
    "$out/$name.log"
done
