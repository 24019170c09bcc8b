#!/usr/bin/env bash
# Exports the demo scene for the web player (gfield export-web, docs/web.md) into
# out/web and serves it on http://127.0.0.1:8000/ (python3's http.server; Ctrl-C stops it).
# Needs scripts/demo.sh's build and assets (out/assets).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-data/scenes/mirror-torus-instances.json}
if [ ! -x build/runtime/gfield-view ] || [ ! -x build/preprocess/gfield ] || [ ! -d out/assets ]; then
  echo "web-demo: run scripts/demo.sh first (it builds gfield, gfield-view and the assets in out/assets)" >&2
  exit 2
fi
build/preprocess/gfield export-web "$scene" --assets out/assets -o out/web
echo "web-demo: open http://127.0.0.1:8000/"
exec python3 -m http.server --bind 127.0.0.1 --directory out/web 8000
