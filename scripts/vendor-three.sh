#!/usr/bin/env bash
# Rebuilds assets/view/three.min.js, the one file of `three` (npm) that
# adair's 3D view embeds: the classes assets/view/three-entry.js names,
# bundled and minified by esbuild into a script that defines `THREE`.
# Needs node and npm; a normal build needs neither (the file is committed).
# Usage: scripts/vendor-three.sh [VERSION]   (default: the newest)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
version="${1:-latest}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
npm init -y >/dev/null
npm install --silent --no-audit --no-fund "three@$version" esbuild >/dev/null
cp "$root/assets/view/three-entry.js" entry.js
v="$(node -p 'JSON.parse(require("fs").readFileSync("node_modules/three/package.json")).version')"
./node_modules/.bin/esbuild entry.js --bundle --minify --format=iife \
  --global-name=THREE --legal-comments=inline --target=es2020 \
  --banner:js="/* three.js $v (npm: three), MIT licence: three.LICENSE beside this file. Bundled by scripts/vendor-three.sh. */" \
  --outfile="$root/assets/view/three.min.js"
cp node_modules/three/LICENSE "$root/assets/view/three.LICENSE"
if grep -qi '</script' "$root/assets/view/three.min.js"; then
  echo "three.min.js contains </script: the page cannot inline it" >&2
  exit 1
fi
echo "three $v -> assets/view/three.min.js ($(wc -c < "$root/assets/view/three.min.js") bytes)"
