#!/usr/bin/env bash
# Builds the meshseg-server container image from deploy/Dockerfile without a
# Docker daemon or a registry: buildah with vfs storage and chroot isolation
# (works as root in a plain VM or container). When the debian:12 base cannot
# be pulled (an offline machine), it is made here with debootstrap from the
# Debian package archive apt already uses, and stored as localhost/debian:12.
# Then it smoke-tests the image (`buildah run`): the binaries start, the user
# is not root, `meshseg info` reads a mesh, `meshseg segment` segments it
# in-process and through a meshseg-server started inside the image on
# loopback (same labels). Prints the build's wall and CPU time and the image size.
#
#   bash scripts/build-image.sh [TAG]          # default TAG meshseg:dev
#   bash scripts/build-image.sh --check [TAG]  # only the smoke test, on a built image
#   MESHSEG_DEBIAN_MIRROR=http://... bash scripts/build-image.sh
#
# Needs root (buildah/debootstrap); not part of the test command (a full
# build inside the image takes tens of minutes on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
CHECK_ONLY=0
if [ "${1:-}" = --check ]; then CHECK_ONLY=1; shift; fi
TAG="${1:-meshseg:dev}"
MIRROR="${MESHSEG_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
export STORAGE_DRIVER=vfs BUILDAH_ISOLATION=chroot
B=(buildah --storage-driver vfs)

for tool in buildah debootstrap; do
  command -v "$tool" >/dev/null || { echo "build-image: $tool not found (bash scripts/setup.sh --image installs it)" >&2; exit 1; }
done

# 1. The base image.
if [ "$CHECK_ONLY" = 1 ]; then
  "${B[@]}" inspect --type image "$TAG" >/dev/null 2>&1 ||
    { echo "build-image: no image $TAG to check (build it first)" >&2; exit 1; }
elif "${B[@]}" inspect --type image debian:12 >/dev/null 2>&1; then
  echo "build-image: base debian:12 already in local storage"
elif timeout 60 "${B[@]}" pull -q docker.io/library/debian:12 >/dev/null 2>&1; then
  echo "build-image: pulled debian:12"
else
  echo "build-image: debian:12 cannot be pulled; making it with debootstrap from $MIRROR"
  ROOTFS=$(mktemp -d /tmp/meshseg-rootfs.XXXXXX)
  trap 'rm -rf "$ROOTFS"' EXIT
  debootstrap --variant=minbase bookworm "$ROOTFS" "$MIRROR" >/tmp/meshseg-debootstrap.log 2>&1 ||
    { tail -20 /tmp/meshseg-debootstrap.log >&2; echo "build-image: debootstrap failed" >&2; exit 1; }
  # The same suites apt on a stock image has (updates and security fixes).
  cat >"$ROOTFS/etc/apt/sources.list" <<EOF
deb $MIRROR bookworm main
deb $MIRROR bookworm-updates main
deb ${MIRROR%/debian}/debian-security bookworm-security main
EOF
  rm -rf "$ROOTFS"/var/cache/apt/archives/*.deb "$ROOTFS"/var/lib/apt/lists/*
  tar -C "$ROOTFS" -cf "$ROOTFS.tar" .
  ctr=$("${B[@]}" from scratch)
  "${B[@]}" add "$ctr" "$ROOTFS.tar" / >/dev/null
  "${B[@]}" config --cmd /bin/bash --env PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "$ctr"
  "${B[@]}" commit -q "$ctr" localhost/debian:12 >/dev/null
  "${B[@]}" rm "$ctr" >/dev/null
  rm -f "$ROOTFS.tar"
fi

# 2. The image (both stages of deploy/Dockerfile; the base is never pulled again).
if [ "$CHECK_ONLY" = 0 ]; then
# The host's ccache directory, when there is one, is lent to the build stage,
# which then builds at this checkout's path so its compilations match the
# host's (MESHSEG_IMAGE_CCACHE=DIR picks another cache, =off builds uncached).
cache=()
cache_dir="${MESHSEG_IMAGE_CCACHE:-}"
if [ -z "$cache_dir" ] && command -v ccache >/dev/null; then cache_dir=$(ccache -k cache_dir); fi
if [ -n "$cache_dir" ] && [ "$cache_dir" != off ]; then
  mkdir -p "$cache_dir"
  cache=(--volume "$cache_dir:/ccache" --build-arg CCACHE_DIR=/ccache --build-arg SRC="$PWD")
  echo "build-image: compiler cache $cache_dir"
fi
/usr/bin/time -f '%e %U %S' -o /tmp/meshseg-image-build.time \
  "${B[@]}" bud --pull=never --layers=false "${cache[@]}" -f deploy/Dockerfile -t "$TAG" . \
  >/tmp/meshseg-image-build.log 2>&1 ||
  { tail -30 /tmp/meshseg-image-build.log >&2; echo "build-image: build failed (full log /tmp/meshseg-image-build.log)" >&2; exit 1; }
read -r wall user sys </tmp/meshseg-image-build.time
echo "build-image: built $TAG in $wall s wall ($user s user + $sys s system CPU)"
fi

# 3. Smoke test inside the image.
ctr=$("${B[@]}" from --pull=never "$TAG")
cleanup_ctr() { "${B[@]}" rm "$ctr" >/dev/null 2>&1 || true; }
trap cleanup_ctr EXIT
run() { "${B[@]}" run "$ctr" -- "$@"; }
uid=$(run id -u)
[ "$uid" != 0 ] || { echo "build-image: the image runs as root" >&2; exit 1; }
run meshseg-server --version
# A real job: a mesh from the shared data (a generated part when it is
# absent) is read, segmented in-process, then segmented again through the
# server started inside the image on loopback; both results must label
# every face and agree face by face.
if [ -f ../shared/data/torus.stl ]; then
  "${B[@]}" copy "$ctr" ../shared/data/torus.stl /tmp/part.stl >/dev/null
else
  run meshseg generate small_block -o /tmp/part.stl
fi
run meshseg info /tmp/part.stl
run meshseg segment /tmp/part.stl -o /tmp/offline.json --step /tmp/part.step >/dev/null
# The STEP writer is the one user of the OpenCASCADE libraries copied into
# the image: its file must be there and be ISO 10303-21.
run sh -c 'head -c 13 /tmp/part.step' | grep -qx 'ISO-10303-21;' ||
  { echo "build-image: meshseg segment --step wrote no STEP file in the image" >&2; exit 1; }
run sh -c '
  meshseg-server --listen 127.0.0.1:0 --spool-dir /tmp/spool >/tmp/server.out 2>/tmp/server.log &
  server=$!
  for _ in $(seq 1 100); do
    addr=$(sed -n "s/^listening on //p" /tmp/server.out)
    [ -n "$addr" ] && break
    sleep 0.1
  done
  [ -n "$addr" ] || { cat /tmp/server.log >&2; echo "server did not start" >&2; exit 1; }
  echo "build-image: server in the image listening on $addr"
  meshseg segment /tmp/part.stl --server "$addr" -o /tmp/served.json >/dev/null
  status=$?
  kill -TERM $server; wait $server
  exit $status'
check=$(mktemp -d /tmp/meshseg-image-check.XXXXXX)
run cat /tmp/offline.json >"$check/offline.json"
run cat /tmp/served.json >"$check/served.json"
python3 - "$check/offline.json" "$check/served.json" <<'PY'
import json, sys
offline, served = (json.load(open(p)) for p in sys.argv[1:3])
labels = offline["face_labels"]
regions = len(offline["regions"])
assert labels and regions > 0 and min(labels) >= -1, "offline result is empty"
assert served["face_labels"] == labels, "the server's labels differ from the offline run's"
assert len(served["regions"]) == regions, "the server's region count differs"
print(f"build-image: job in the image: {len(labels)} faces, {regions} regions, offline == served")
PY
rm -rf "$check"
# (buildah reports the probe's exit status 1, the expected answer, on stderr.)
if run sh -c 'ls /usr/include 2>/dev/null | grep -q grpcpp' 2>/dev/null; then
  echo "build-image: development headers found in the runtime image" >&2; exit 1
fi
size=$("${B[@]}" images --format '{{.Size}}' "$TAG" | head -1)
echo "build-image: $TAG OK: runs as uid $uid, image size $size"
