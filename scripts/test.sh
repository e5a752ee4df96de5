#!/usr/bin/env bash
# Every test: installs what it needs (npm packages, Debian's chromium and, where it can, firefox-esr), type-checks, runs
# the engine's tests in Node (mocha), then the element, worker and drawing tests in chromium with @web/test-runner, the
# gallery checks, and the end-to-end pages (builds across origins, CSP, the npm tarball, an app's bundlers, layout
# shift, phone gestures, many embeds on one worker pool).
# Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each section's heading says how long the run has taken so far, to see where the quarter of an hour goes.
section() { echo "== $* ($((SECONDS / 60)) min $((SECONDS % 60)) s in)"; }
bash scripts/ensure-deps.sh
bash scripts/ensure-chromium.sh
bash scripts/ensure-firefox.sh
section "typecheck"
npx tsc --noEmit -p tsconfig.json
npx tsc --noEmit -p test/tsconfig.json
section "the WebAssembly kernel's bytes up to date with its source"
node scripts/build-wasm.mjs --check
section "custom-elements.json up to date"
cp custom-elements.json /tmp/custom-elements.committed.json
npm run analyze --silent >/dev/null
cmp -s /tmp/custom-elements.committed.json custom-elements.json || { echo "custom-elements.json was out of date (regenerated now): commit it"; exit 1; }
section "docs/elements.md up to date with custom-elements.json"
node scripts/docs-elements.mjs --check
section "engine tests in Node, twice at once: default kernel 'js' (the JS solver) and 'wasm' (the WebAssembly SIMD kernel; its setup fails the run if it does not run)"
# Side by side on the machine's two cores (each pass is one busy process): about two minutes instead of four.
logs=$(mktemp -d)
npx mocha > "$logs/js.log" 2>&1 & js=$!
npx mocha --require test/engine/kernel/wasm-default.setup.ts > "$logs/wasm.log" 2>&1 & wasm=$!
js_rc=0; wait "$js" || js_rc=$?
wasm_rc=0; wait "$wasm" || wasm_rc=$?
echo "-- kernel 'js'"; cat "$logs/js.log"
echo "-- kernel 'wasm'"; cat "$logs/wasm.log"
rm -rf "$logs"
[ "$js_rc" = 0 ] && [ "$wasm_rc" = 0 ] || { echo "engine tests failed (kernel 'js': exit $js_rc, kernel 'wasm': exit $wasm_rc)"; exit 1; }
section "engine in Node: allocation per step, soak"
node scripts/engine-in-node.mjs
node --expose-gc scripts/soak.mjs --steps 30000 --samples 5
section "browser tests"
npx web-test-runner --static-logging "$@"
section "gallery stories"
node scripts/check-stories.mjs
section "gallery layout and accessibility (axe at 1280 and 390 px)"
node scripts/check-gallery.mjs
section "browser soak: 1 minute of markup changes (long form: node scripts/browser-soak.mjs --minutes 15)"
node scripts/browser-soak.mjs --minutes 1
section "build, the single-file build embedded across origins, both builds under a strict CSP"
npm run build --silent
section "sizes within the issues' budgets (single file with p5 <= 175 KB gzip, the kernel's share <= 10 KB)"
node scripts/sizes.mjs --check
node test/e2e/cross-origin.mjs
node test/e2e/csp.mjs
section "the npm tarball installed and embedded from a second origin (chromium; Firefox ESR when installed)"
node test/e2e/pack.mjs --no-build
section "an app's bundlers: Vite and webpack bundle the library and its worker, esbuild the single file"
node test/e2e/bundlers.mjs
section "no layout shift while the embed loads (1.6 Mbit/s, 150 ms; desktop and phone)"
node scripts/measure-loading.mjs --runs 1 --max-cls 0.02
section "phone: swipes scroll past the scene, a body drags, pinch zooms"
node test/e2e/phone.mjs
section "many embeds: 8 cloths in a post share the worker pool"
node test/e2e/many-embeds.mjs --runs 1
section "all passed"
