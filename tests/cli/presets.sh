#!/bin/bash
# The functional trees on the screen, end to end: presets.sh. Every preset (presets/*.yaml,
# through --generate) from the front and turned, in its own season and the next (the
# season button), a winter tree, the New strip (in both languages) and the parameter
# buttons at a limit, against golden pictures in tests/golden/presets/ at 640x400 (small:
# the repository keeps them). Paths come from meson's environment: EDAHA, IMGCMP, SRC (the
# source tree's tests/ folder). With EDAHA_UPDATE_GOLDEN=1 it writes the pictures instead:
# look at every one before committing it.
set -uo pipefail
: "${EDAHA:?}" "${SRC:?}" "${IMGCMP:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-presets.XXXXXX")
trap 'rm -rf "$T"' EXIT
PRESETS=$SRC/../presets
GOLDEN=$SRC/golden/presets
SIZE=640x400
# turned: a little from the right and above, so the crowns read as 3D
TURNED=45,15
fails=0

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
run() { # name args...: the screen of a headless run, as $T/name.png
	local name=$1 rc=0
	shift
	edaha --headless --size "$SIZE" --out "$T/$name" "$@" >"$T/stdout" 2>"$T/stderr" || rc=$?
	[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha $* exited $rc"; }
	cp "$T/$name/screen.png" "$T/$name.png"
}
# Compares $T/name.png with its golden (or writes the golden); every mismatch is reported
# before the script fails.
golden() {
	local name=$1
	if [ "${EDAHA_UPDATE_GOLDEN:-0}" = 1 ]; then
		mkdir -p "$GOLDEN"
		cp "$T/$name.png" "$GOLDEN/$name.png"
		echo "presets.sh: updated $GOLDEN/$name.png"
		return
	fi
	if ! "$IMGCMP" "$GOLDEN/$name.png" "$T/$name.png"; then
		echo "FAIL: $name differs from its golden" >&2
		fails=$((fails + 1))
	fi
}

n=0
for file in "$PRESETS"/*.yaml; do
	p=$(basename "$file" .yaml)
	n=$((n + 1))
	run "$p-front" --generate "$file"
	run "$p-turned" --generate "$file" --view "$TURNED"
	run "$p-next-front" --generate "$file" --press season
	run "$p-next-turned" --generate "$file" --press season --view "$TURNED"
	# the camera and the season change the picture, never the branches
	cmp -s "$T/$p-front/skeleton.json" "$T/$p-turned/skeleton.json" ||
		fail "$p: turning changed the skeleton"
	cmp -s "$T/$p-front.png" "$T/$p-turned.png" && fail "$p: turning changed nothing"
	cmp -s "$T/$p-front.png" "$T/$p-next-front.png" && fail "$p: the season changed nothing"
	cmp -s <(sed 's/"season":"[a-z]*"//' "$T/$p-front/skeleton.json") \
		<(sed 's/"season":"[a-z]*"//' "$T/$p-next-front/skeleton.json") ||
		fail "$p: the season changed the skeleton's branches or leaves"
	for v in front turned next-front next-turned; do
		golden "$p-$v"
	done
done
[ $n -eq 6 ] || fail "$n presets, wanted 6"

# winter: the branches alone
run zelkova-winter --generate "$PRESETS/zelkova.yaml" --press season --press season
golden zelkova-winter
# the New strip: a blank card and the six presets, with their names
run new --press new
golden new
run new-ja --press new --lang ja
golden new-ja
# the parameter buttons on a palm down to its fewest fronds (14 - 6 x 2; the presses past
# that do nothing): Fewer is drawn disabled
args=()
for _ in 1 2 3 4 5 6 7 8; do args+=(--press gen-fewer); done
run palm-fewest --generate "$PRESETS/palm.yaml" "${args[@]}"
grep -c '^generate ' "$T/palm-fewest/drawing.edaha" | grep -qx 7 || fail "palm-fewest: not 1 + 6 generate ops"
golden palm-fewest

[ "$fails" -eq 0 ] || fail "$fails pictures differ from their goldens"
echo "presets.sh: $n presets, $((n * 4 + 4)) pictures"
