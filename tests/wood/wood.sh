#!/bin/bash
# SPDX-License-Identifier: MIT
# The grow button on the command line (issue 17, seed 002): edaha --headless ... --press
# grow [--wood FILE] [--dump-voxels] --out DIR, end to end: wood.sh TEST. Paths come from
# meson's environment: EDAHA, IMGCMP, GLTF_VALIDATE, SRC (the source tree). With
# EDAHA_UPDATE_GOLDEN=1, `golden` writes tests/wood/golden/ instead of comparing: look at
# every picture before committing it.
set -uo pipefail
: "${EDAHA:?}" "${IMGCMP:?}" "${GLTF_VALIDATE:?}" "${SRC:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-wood.XXXXXX")
trap 'rm -rf "$T"' EXIT
DEMO=$SRC/tests/data/demo.edaha-trace
CHECK=$SRC/tests/wood/check_voxels.py

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
run() { # run ARGS...: a headless run that must succeed
	local rc=0
	edaha --headless "$@" >"$T/stdout" 2>"$T/stderr" || rc=$?
	[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha $* exited $rc"; }
}

# Two presses on the demo's tree: the drawing holds them, the dumped voxels are at rest
# and their forces are the springs', and the drawing replays to the same files.
t_dump() {
	run --replay "$DEMO" --press 3d --press grow --press grow --dump-voxels --out "$T/a"
	[ "$(grep -c '^grow [0-9]* {edaha-wood: 1, mode: broadleaf, grid: 64,' "$T/a/drawing.edaha")" = 2 ] ||
		fail "the drawing does not hold two grow presses"
	grep -q '"step":2' "$T/a/voxels.json" || fail "voxels.json does not say two presses"
	python3 "$CHECK" "$T/a" || fail "the dumped voxels are not at rest"
	run --load "$T/a/drawing.edaha" --dump-voxels --out "$T/b"
	for f in voxels.json voxels.bin skeleton.json model.glb model.obj drawing.edaha; do
		cmp -s "$T/a/$f" "$T/b/$f" || fail "$f differs after --load"
	done
	echo "two presses dumped at rest and replayed"
}

# A settings file: conifer, in the drawing; no gravity, no growth; bad files refused.
t_settings() {
	printf 'edaha-wood: 1\nmode: conifer\ngravity: 0\n' >"$T/still.yaml"
	run --replay "$DEMO" --press 3d --press grow --press grow --press grow --wood "$T/still.yaml" \
		--dump-voxels --out "$T/s"
	grep -q '^grow [0-9]* {edaha-wood: 1, mode: conifer, grid: 64, alpha: 20000, beta: 1, gravity: 0,' \
		"$T/s/drawing.edaha" || fail "the conifer settings are not in the drawing"
	python3 - "$T/s" <<'PY' || fail "without gravity the wood grew"
import sys
from array import array
import json
d = sys.argv[1]
m = json.load(open(d + "/voxels.json"))
raw = open(d + "/voxels.bin", "rb").read()
n = m["dims"][0] * m["dims"][1] * m["dims"][2]
f = m["fields"]
a = raw[f["density0"]["offset"]:f["density0"]["offset"] + 8 * n]
b = raw[f["density"]["offset"]:f["density"]["offset"] + 8 * n]
sys.exit(0 if a == b else 1)
PY
	printf 'edaha-wood: 1\nmode: oak\n' >"$T/bad.yaml"
	local rc=0
	edaha --headless --replay "$DEMO" --press grow --wood "$T/bad.yaml" --out "$T/x" \
		>/dev/null 2>"$T/err" || rc=$?
	[ $rc -eq 2 ] || fail "a bad --wood file: exit $rc, wanted 2"
	grep -qF "edaha: $T/bad.yaml:2: mode:" "$T/err" || { cat "$T/err"; fail "no FILE:LINE"; }
	[ ! -e "$T/x" ] || fail "a bad --wood file wrote output"
	rc=0
	edaha --headless --replay "$DEMO" --dump-voxels --out "$T/y" >/dev/null 2>"$T/err" || rc=$?
	[ $rc -eq 2 ] || fail "--dump-voxels of a tree never grown: exit $rc, wanted 2"
	[ ! -e "$T/y" ] || fail "--dump-voxels of a tree never grown wrote output"
	edaha --dump-voxels >/dev/null 2>"$T/err" && fail "--dump-voxels without --headless ran"
	grep -q "needs --headless" "$T/err" || fail "--dump-voxels without --headless: no usage error"
	echo "settings in the drawing, still without gravity, bad input refused"
}

# golden NAME DIR: DIR/screen.png against tests/wood/golden/NAME.png (or written there)
golden() {
	if [ "${EDAHA_UPDATE_GOLDEN:-0}" = 1 ]; then
		mkdir -p "$SRC/tests/wood/golden"
		cp "$2/screen.png" "$SRC/tests/wood/golden/$1.png"
		echo "wood.sh: updated tests/wood/golden/$1.png"
	elif ! "$IMGCMP" "$SRC/tests/wood/golden/$1.png" "$2/screen.png"; then
		fail "$1: screen.png differs from its golden tests/wood/golden/$1.png"
	fi
}

# The pictures: the demo's tree after 0, 3 and 8 presses; a trunk leaning 45 degrees
# (tests/wood/data/leaning-trunk.json) after 5 as a conifer and as a broadleaf tree; their
# exports validate.
t_golden() {
	local presses n
	for n in 0 3 8; do
		presses=()
		for ((i = 0; i < n; i++)); do presses+=(--press grow); done
		run --size 640x400 --replay "$DEMO" --press 3d "${presses[@]}" --view 25,10 \
			--out "$T/d$n"
		golden "drawn-$n" "$T/d$n"
	done
	"$GLTF_VALIDATE" "$T/d8/model.glb" || fail "the grown tree's glb does not validate"
	for m in conifer broadleaf; do
		run --size 640x400 --skeleton "$SRC/tests/wood/data/leaning-trunk.json" \
			--wood "$SRC/tests/wood/data/wood-$m.yaml" --press grow --press grow --press grow \
			--press grow --press grow --view 0,10 --out "$T/$m"
		golden "leaning-$m-5" "$T/$m"
		"$GLTF_VALIDATE" "$T/$m/model.glb" || fail "the leaning $m's glb does not validate"
	done
	echo "five pictures of grown wood as their goldens, their exports valid"
}

"t_$1"
