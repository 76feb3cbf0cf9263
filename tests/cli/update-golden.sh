#!/bin/bash
# Regenerates the end-to-end goldens from the demo trace: tests/cli/update-golden.sh BUILDDIR
# Look at tests/golden/demo-screen.png before committing it.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$build/platform/edaha" --headless --out "$out" --replay tests/data/demo.edaha-trace
cp "$out/screen.png" tests/golden/demo-screen.png
cp "$out/skeleton.json" tests/golden/demo-skeleton.json
cp "$out/screen.png" docs/screenshot.png
echo "updated tests/golden/demo-screen.png, demo-skeleton.json and docs/screenshot.png"
