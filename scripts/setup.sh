#!/usr/bin/env bash
# Installs every Debian 12 package meshseg needs to build, test and run.
# Idempotent and non-interactive; runs as root or through sudo.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libgrpc++-dev libgrpc-dev protobuf-compiler-grpc libprotobuf-dev protobuf-compiler
  libabsl-dev libeigen3-dev libopenmesh-dev
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  libtbb-dev libcgal-dev libboost-graph-dev libnanoflann-dev
  libhiredis-dev redis-server
  libssl-dev
  python3 python3-grpcio python3-protobuf python3-pil chromium openssl
  time
  nodejs
  prometheus
  clang-14 libclang-rt-14-dev
  # brep stage (STEP export): OpenCASCADE 7.6; the CMake config's components
  # FoundationClasses ... DataExchange need all five -dev packages.
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-ocaf-dev libocct-visualization-dev libocct-data-exchange-dev
  zlib1g-dev
)
# scripts/build-image.sh's tools (the image is built without Docker): only
# with `bash scripts/setup.sh --image`, so the image's own build stage, which
# runs this script, does not install them.
if [ "${1:-}" = --image ]; then PACKAGES+=(buildah debootstrap); fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# npm (deploy/ validation): Debian's package, unless the installed node
# already ships it (NodeSource's nodejs does, and conflicts with Debian's npm).
if ! command -v npm >/dev/null 2>&1; then
  missing+=(npm)
fi

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
