#!/usr/bin/env bash
# Installs the npm packages when node_modules is missing or older than package.json / package-lock.json.
# (`npm ci` does not work here: the lock file lacks other platforms' native rollup binaries.)
set -euo pipefail
stamp=node_modules/.package-lock.json
if [ ! -f "$stamp" ] || [ package.json -nt "$stamp" ] || { [ -f package-lock.json ] && [ package-lock.json -nt "$stamp" ]; }; then
  npm install --no-audit --no-fund
fi
