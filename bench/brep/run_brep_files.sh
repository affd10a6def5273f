#!/usr/bin/env bash
# The brep stage on the real CAD meshes of shared/data: each file segmented
# once (meshseg segment), the B-rep written from the saved result (meshseg
# brep, timed: wall, CPU, peak RSS) and read back (brep_timing --check:
# validity, solids, shells, faces, free edges, volume against the mesh's).
# Usage: bench/brep/run_brep_files.sh [BUILD_DIR] [OUT_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
out=${2:-/tmp/brep_files}
data=$root/../shared/data
mkdir -p "$out"
files=(
  fandisk.off plate_holes.stl abc_00007974_5.obj
  cad/hducg_MFCAD__1-5-7-10-14-23.obj cad/hducg_MFCAD__3-7-11-13-14-23.obj
  cad/hducg_MFCAD__7-10-11-11-14-23.obj cad/whjdark_AAGNet__partA.obj
  cad/whjdark_AAGNet__partB.obj cad/whjdark_AAGNet__partC.obj cad/whjdark_AAGNet__test.obj
  cad/xupeiwust_hierarchical-cadnet__1_true.obj cad/xupeiwust_hierarchical-cadnet__3_true.obj
  cad/xupeiwust_hierarchical-cadnet__4_true.obj cad/xupeiwust_hierarchical-cadnet__6_true.obj
  cad/mikedh_trimesh__base_interface_AP214.obj
  cad/deep-geometry_abc-dataset__00000050_80d90bfdd2e74e709956122a_step_000.obj
)
for f in "${files[@]}"; do
  name=$(basename "${f%.*}")
  echo "== $f"
  [[ -s $out/$name.json ]] || "$build/bin/meshseg" segment "$data/$f" -o "$out/$name.json" >/dev/null
  rm -f "$out/$name.step"
  /usr/bin/time -f "brep %e s wall, %U s user + %S s sys, peak %M KiB" \
    "$build/bin/meshseg" brep "$out/$name.json" "$data/$f" -o "$out/$name.step" |
    grep -v '^wrote' || true
  if [[ -s $out/$name.step ]]; then
    "$build/bin/brep_timing" --check "$out/$name.step" "$data/$f"
  fi
done
