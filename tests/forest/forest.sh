#!/bin/bash
# SPDX-License-Identifier: MIT
# Today's forest with grown trees and vines on the command line (issue 27, docs/forest.md
# "The wood and the vines"): edaha --headless --forest DIR --out OUT, end to end:
# forest.sh TEST. Paths come from meson's environment: EDAHA, IMGCMP, SRC (the source
# tree). With EDAHA_UPDATE_GOLDEN=1, `grown` writes tests/forest/golden/ instead of
# comparing: look at every picture before committing it.
set -uo pipefail
: "${EDAHA:?}" "${IMGCMP:?}" "${SRC:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-forest.XXXXXX")
trap 'rm -rf "$T"' EXIT
DEMO=$SRC/tests/data/demo.edaha-trace
TAP=$SRC/tests/data/vine-tap.edaha-trace

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
run() { # run ARGS...: a headless run that must succeed
	local rc=0
	edaha --headless "$@" >"$T/stdout" 2>"$T/stderr" || rc=$?
	[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha $* exited $rc"; }
}

# golden NAME DIR: DIR/screen.png against tests/forest/golden/NAME.png (or written there)
golden() {
	if [ "${EDAHA_UPDATE_GOLDEN:-0}" = 1 ]; then
		mkdir -p "$SRC/tests/forest/golden"
		cp "$2/screen.png" "$SRC/tests/forest/golden/$1.png"
		echo "forest.sh: updated tests/forest/golden/$1.png"
	elif ! "$IMGCMP" "$SRC/tests/forest/golden/$1.png" "$2/screen.png"; then
		fail "$1: screen.png differs from its golden tests/forest/golden/$1.png"
	fi
}

# Grown trees and vines as visitors make them: the demo made 3D, grown and given a vine;
# cherry grown twice; zelkova grown twice and given a vine. Three of them stand at full
# detail (the wood's bark where its branches' thin tubes were, the vines climbing); twelve
# share the forest's triangles, each within its share (the wood and the stems made
# coarser, the leaves as cards). The same run twice, the same picture.
t_grown() {
	local kinds=(demo cherry zelkova) i
	run --out "$T/demo" --replay "$DEMO" --press 3d --press grow --press vine --replay "$TAP"
	run --out "$T/cherry" --press tpl-cherry --press grow --press grow
	run --out "$T/zelkova" --press tpl-zelkova --press grow --press grow --press vine \
		--replay "$TAP"
	for k in demo zelkova; do
		grep -q '^vine ' "$T/$k/drawing.edaha" || fail "the $k drawing holds no vine"
	done
	for k in "${kinds[@]}"; do
		grep -q '^grow ' "$T/$k/drawing.edaha" || fail "the $k drawing holds no grow press"
	done
	mkdir -p "$T/three" "$T/twelve"
	for i in 0 1 2; do
		cp "$T/${kinds[$i]}/drawing.edaha" "$T/three/$i-${kinds[$i]}.edaha"
	done
	for i in $(seq -w 0 11); do
		cp "$T/${kinds[$((10#$i % 3))]}/drawing.edaha" "$T/twelve/$i.edaha"
	done
	run --forest "$T/three" --out "$T/f3"
	run --forest "$T/twelve" --out "$T/f12" --idle 40
	run --forest "$T/twelve" --out "$T/f12b" --idle 40
	cmp -s "$T/f12/screen.png" "$T/f12b/screen.png" || fail "the same forest drew differently"
	golden grown-3 "$T/f3"
	golden grown-12 "$T/f12"
	echo "forests of 3 and 12 grown and vined trees as their goldens"
}

"t_$1"
