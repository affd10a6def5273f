#!/usr/bin/env bash
# Validates deploy/ offline: every Kubernetes object (and KEDA's
# ScaledObject) against its published schema, and compose.yaml against the
# Compose Specification, with the pinned npm packages of deploy/validate
# (installed here from package-lock.json on first use). Exits non-zero on
# any invalid object. ctest runs it (test deploy_manifests_valid).
set -euo pipefail
cd "$(dirname "$0")/../deploy/validate"

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  echo "validate_deploy: node and npm are needed (bash scripts/setup.sh installs them)" >&2
  exit 1
fi
# Reinstall only when the lock file changed since the last install.
if ! cmp -s package-lock.json node_modules/.meshseg-installed-lock 2>/dev/null; then
  npm ci --no-audit --no-fund --loglevel=error >/dev/null
  cp package-lock.json node_modules/.meshseg-installed-lock
fi
exec node validate.mjs
