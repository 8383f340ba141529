#!/usr/bin/env bash
# Installs playwright-core (pinned by package-lock.json) next to this script, again only when the
# lock file changed. It drives Debian's /usr/bin/chromium; it downloads no browser.
set -euo pipefail
cd "$(dirname "$0")"
cmp -s package-lock.json node_modules/.installed-lock 2>/dev/null && exit 0
npm ci --no-audit --no-fund --loglevel=error
cp package-lock.json node_modules/.installed-lock
