#!/usr/bin/env bash
# Segments every labelled CAD mesh of ../shared/data (cad/ gmsh and CAD-export
# tessellations, abc_00007974_5) with MESHSEG (default build/bin/meshseg) and
# scores each result with score_cad.py; one row per file.
# usage: bench/cad/run_cad_files.sh [MESHSEG] [OUT_DIR]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
meshseg="${1:-$here/../../build/bin/meshseg}"
out="${2:-/tmp/meshseg_cad_results}"
data="$here/../../../shared/data"
mkdir -p "$out"
score() {  # mesh labels yml
  local name; name="$(basename "$1")"
  local start end
  start=$(date +%s.%N)
  if ! timeout 900 "$meshseg" segment "$1" -o "$out/$name.json" >/dev/null 2>"$out/$name.err"; then
    echo "$name: FAILED $(tail -1 "$out/$name.err")"; return
  fi
  end=$(date +%s.%N)
  python3 "$here/score_cad.py" "$1" "$2" "$3" "$out/$name.json" --time "$(echo "$end - $start" | bc)"
}
for obj in "$data"/cad/*.obj; do
  base="${obj%.obj}"
  case "$base" in
    *_stl) yml="${base%_stl}_features.yml"
           [ -f "$yml" ] || yml="$(ls "${base%_trimesh_000_stl}"_step_000_features.yml 2>/dev/null || true)" ;;
    *) yml="${base}_features.yml" ;;
  esac
  score "$obj" "$base.face_labels.txt" "$yml"
done
score "$data/abc_00007974_5.obj" - "$data/abc_00007974_5.yml"
