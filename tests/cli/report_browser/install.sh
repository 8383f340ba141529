#!/usr/bin/env bash
# Installs playwright-core (pinned by package-lock.json) next to this script, once. It drives
# Debian's /usr/bin/chromium; it downloads no browser.
set -euo pipefail
cd "$(dirname "$0")"
[ -f node_modules/playwright-core/package.json ] && exit 0
npm ci --no-audit --no-fund --loglevel=error
