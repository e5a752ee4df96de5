#!/usr/bin/env bash
# Starts the demo: installs the npm packages if needed, then serves the repo (TypeScript compiled on the fly, with
# COOP/COEP so the SharedArrayBuffer path runs; `/` redirects to the gallery at /demo/).
# PORT chooses the port (default 8000): PORT=8123 npm start
set -euo pipefail
cd "$(dirname "$0")/.."
PORT="${PORT:-8000}"
if ! [[ "$PORT" =~ ^[1-9][0-9]{0,4}$ ]] || (( PORT > 65535 )); then
  echo "npm start: PORT must be a port number from 1 to 65535, got \"$PORT\"" >&2
  exit 1
fi
bash scripts/ensure-deps.sh
# The dev server reports a busy port with a stack trace and exit status 0: look just before starting it.
node -e '
  const port = Number(process.argv[1]);
  const server = require("node:net").createServer();
  server.once("error", (e) => {
    const how = e.code === "EADDRINUSE" ? "is already in use" : `cannot be used (${e.code})`;
    const other = port < 65535 ? port + 1 : 8000;
    console.error(`npm start: port ${port} ${how}; choose another with PORT, e.g. PORT=${other} npm start`);
    process.exit(1);
  });
  server.listen(port, "0.0.0.0", () => server.close());
' "$PORT"
echo "physics-elements demo: http://localhost:${PORT}/ (redirects to the gallery, /demo/)"
exec node_modules/.bin/web-dev-server --config web-dev-server.config.js --port "$PORT" --hostname 0.0.0.0 "$@"
