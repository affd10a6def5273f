#!/usr/bin/env bash
# Installs dependencies, builds everything with Ninja, and runs the whole
# GoogleTest suite through ctest. Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
cmake --preset default
cmake --build --preset default
ctest --preset default -j "$(nproc)" --output-on-failure
