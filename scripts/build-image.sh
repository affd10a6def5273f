#!/usr/bin/env bash
# Builds the meshseg-server container image from deploy/Dockerfile without a
# Docker daemon or a registry: buildah with vfs storage and chroot isolation
# (works as root in a plain VM or container). When the debian:12 base cannot
# be pulled (an offline machine), it is made here with debootstrap from the
# Debian package archive apt already uses, and stored as localhost/debian:12.
# Then it smoke-tests the image (`buildah run`): the binaries start, the user
# is not root, `meshseg info` reads a mesh. Prints the image size.
#
#   bash scripts/build-image.sh [TAG]          # default TAG meshseg:dev
#   MESHSEG_DEBIAN_MIRROR=http://... bash scripts/build-image.sh
#
# Needs root (buildah/debootstrap); not part of the test command (a full
# build inside the image takes tens of minutes on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
TAG="${1:-meshseg:dev}"
MIRROR="${MESHSEG_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
export STORAGE_DRIVER=vfs BUILDAH_ISOLATION=chroot
B=(buildah --storage-driver vfs)

for tool in buildah debootstrap; do
  command -v "$tool" >/dev/null || { echo "build-image: $tool not found (bash scripts/setup.sh --image)" >&2; exit 1; }
done

# 1. The base image.
if "${B[@]}" inspect --type image debian:12 >/dev/null 2>&1; then
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
start=$(date +%s)
"${B[@]}" bud --pull=never --layers=false -f deploy/Dockerfile -t "$TAG" . >/tmp/meshseg-image-build.log 2>&1 ||
  { tail -30 /tmp/meshseg-image-build.log >&2; echo "build-image: build failed (full log /tmp/meshseg-image-build.log)" >&2; exit 1; }
echo "build-image: built $TAG in $(( $(date +%s) - start )) s"

# 3. Smoke test inside the image.
ctr=$("${B[@]}" from --pull=never "$TAG")
cleanup_ctr() { "${B[@]}" rm "$ctr" >/dev/null 2>&1 || true; }
trap cleanup_ctr EXIT
run() { "${B[@]}" run "$ctr" -- "$@"; }
uid=$(run id -u)
[ "$uid" != 0 ] || { echo "build-image: the image runs as root" >&2; exit 1; }
run meshseg-server --version
# A real mesh from the shared data (a generated part when it is absent).
if [ -f ../shared/data/torus.stl ]; then
  "${B[@]}" copy "$ctr" ../shared/data/torus.stl /tmp/part.stl >/dev/null
  run meshseg info /tmp/part.stl
else
  run meshseg generate test_piece -o /tmp/part.stl && run meshseg info /tmp/part.stl
fi
# (buildah reports the probe's exit status 1, the expected answer, on stderr.)
if run sh -c 'ls /usr/include 2>/dev/null | grep -q grpcpp' 2>/dev/null; then
  echo "build-image: development headers found in the runtime image" >&2; exit 1
fi
size=$("${B[@]}" images --format '{{.Size}}' "$TAG" | head -1)
echo "build-image: $TAG OK: runs as uid $uid, image size $size"
