#!/bin/sh
# Builds ../assets/viewer.bundle.js, the script walls-preview's HTML page embeds: viewer.js
# with three.js and its OrbitControls, from the npm packages locked in package-lock.json,
# bundled by esbuild into one minified IIFE (three's licence comment kept at its end).
# The bundle is committed so that `cargo build` needs no npm; scripts/test rebuilds it and
# fails if it differs from the committed file.
set -eu
cd "$(dirname "$0")"
npm ci --no-audit --no-fund --loglevel=error
mkdir -p ../assets
node_modules/.bin/esbuild viewer.js --bundle --format=iife --minify \
  --legal-comments=eof --charset=utf8 --log-level=warning \
  --outfile=../assets/viewer.bundle.js
