#!/usr/bin/env bash
# Starts the demo: installs the npm packages if needed, then serves the repo (TypeScript compiled on the fly, with
# COOP/COEP so the SharedArrayBuffer path runs) and prints the demo's address.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure-deps.sh
PORT="${PORT:-8000}"
echo "physics-elements demo: http://localhost:${PORT}/demo/"
exec npx web-dev-server --config web-dev-server.config.js --port "$PORT" --hostname 0.0.0.0 "$@"
