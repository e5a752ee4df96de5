#!/usr/bin/env bash
# Tries to install Debian's firefox-esr when it is missing (test/e2e/pack.mjs also embeds the package in Firefox ESR,
# driven by puppeteer-core over WebDriver BiDi). Never fails: where it cannot be installed, pack.mjs says SKIP and why.
if [ -n "${FIREFOX_PATH:-}" ] && [ -x "$FIREFOX_PATH" ]; then exit 0; fi
if [ -x /usr/bin/firefox-esr ]; then exit 0; fi
echo "Installing Debian's firefox-esr (once)..."
SUDO=""
[ "$(id -u)" = 0 ] || SUDO="sudo"
{ $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq firefox-esr >/dev/null; } \
  || echo "firefox-esr could not be installed: the Firefox part of test/e2e/pack.mjs will be skipped"
exit 0
