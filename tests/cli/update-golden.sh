#!/bin/bash
# Regenerates the end-to-end goldens from the demo trace: tests/cli/update-golden.sh BUILDDIR
# Look at every regenerated image before committing it.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$build/platform/edaha" --headless --out "$out" --replay tests/data/demo.edaha-trace
cp "$out/screen.png" tests/golden/demo-screen.png
cp "$out/skeleton.json" tests/golden/demo-skeleton.json
cp "$out/screen.png" docs/screenshot.png
# the 3D trees from the front and turned by 90 degrees (cli.sh t_views, VIEW_SKETCHES)
for name in demo orbit lift-young lift-broadleaf lift-conifer lift-sine sketch-fan sketch-fan-outlines; do
	"$build/platform/edaha" --headless --out "$out/$name-front" --replay "tests/data/$name.edaha-trace" --press 3d --view 0
	"$build/platform/edaha" --headless --out "$out/$name-90" --replay "tests/data/$name.edaha-trace" --press 3d --view 90
	cp "$out/$name-front/screen.png" "tests/golden/$name-3d-front.png"
	cp "$out/$name-90/screen.png" "tests/golden/$name-3d-90.png"
done
"$build/platform/edaha" --headless --out "$out/leaf" --replay tests/data/edit-leaf-suggest.edaha-trace
cp "$out/leaf/screen.png" tests/golden/edit-leaf-suggest.png
# fans of branches (cli.sh t_golden)
for name in sketch-fan sketch-fan-outlines; do
	"$build/platform/edaha" --headless --out "$out/$name" --replay "tests/data/$name.edaha-trace"
	cp "$out/$name/screen.png" "tests/golden/$name-screen.png"
done
# the labels in Japanese, and the attract screen (cli.sh t_lang, t_idle)
"$build/platform/edaha" --headless --out "$out/ja" --replay tests/data/demo.edaha-trace --lang ja
cp "$out/ja/screen.png" tests/golden/demo-screen-ja.png
"$build/platform/edaha" --headless --out "$out/idle" --replay tests/data/demo.edaha-trace --idle 120
cp "$out/idle/screen.png" tests/golden/demo-attract.png
"$build/platform/edaha" --headless --out "$out/idle-ja" --replay tests/data/demo.edaha-trace --idle 120 --lang ja
cp "$out/idle-ja/screen.png" tests/golden/demo-attract-ja.png
echo "updated tests/golden/edit-leaf-suggest.png, sketch-fan*-screen.png, demo-screen-ja.png, demo-attract.png, demo-attract-ja.png; tests/golden/demo-screen.png, demo-skeleton.json, *-3d-front.png, *-3d-90.png and docs/screenshot.png"
