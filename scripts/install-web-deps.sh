#!/usr/bin/env bash
# Installs the web package's npm modules (web/package-lock.json: three and three-mesh-bvh, which
# gfield-view --export-web copies into an export for the page's three-mesh-bvh method, and
# puppeteer-core, which drives Debian's chromium in the web player's test) into web/node_modules
# with `npm ci`, when they are missing or older than the lock file. Idempotent; retries the
# registry three times.
set -euo pipefail
cd "$(dirname "$0")/../web"
marker=node_modules/.gfield-installed
if [ -f "$marker" ] && [ "$marker" -nt package-lock.json ]; then
  echo "install-web-deps: up to date (web/node_modules)"
  exit 0
fi
for attempt in 1 2 3; do
  if npm ci --prefer-offline --no-audit --no-fund --loglevel=error --fetch-retries=4 \
    --fetch-retry-mintimeout=2000 --fetch-retry-maxtimeout=30000; then
    touch "$marker"
    echo "install-web-deps: installed web/node_modules"
    exit 0
  fi
  echo "install-web-deps: npm ci failed (attempt $attempt of 3)" >&2
  [ "$attempt" -lt 3 ] && sleep $((attempt * 15))
done
exit 1
