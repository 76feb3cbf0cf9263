#!/bin/bash
# SPDX-License-Identifier: MIT
# seasons.sh: the edaha binary's exports of one tree in every season, end to end. Paths
# come from meson's environment: EDAHA, CHECK_SEASONS, GLTF_VALIDATE, PRESET (a preset
# whose leaves start in spring, e.g. presets/cherry.yaml), EDAHA_GL_PRELOAD (ASan builds).
# Each press of the season button: spring -> summer -> autumn -> winter. Every model.glb
# passes the Khronos validator without an error or a warning, every model.glb and
# model.obj reads back in assimp (where installed), and check_seasons compares the files.
set -uo pipefail
: "${EDAHA:?}" "${CHECK_SEASONS:?}" "${GLTF_VALIDATE:?}" "${PRESET:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-seasons.XXXXXX")
trap 'rm -rf "$T"' EXIT

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"

seasons="spring summer autumn winter"
presses=()
dirs=()
for s in $seasons; do
	edaha --headless --generate "$PRESET" "${presses[@]}" --out "$T/$s" >"$T/log" 2>&1 ||
		{ cat "$T/log" >&2; fail "edaha --generate $PRESET ${presses[*]} exited $?"; }
	grep -q "\"season\":\"$s\"" "$T/$s/skeleton.json" || fail "$s: skeleton.json is not in $s"
	dirs+=("$T/$s")
	presses+=(--press season)
done

"$GLTF_VALIDATE" "$T"/*/model.glb >"$T/validator.log" 2>&1
rc=$?
cat "$T/validator.log"
[ $rc -eq 0 ] || fail "glTF validator"
for s in $seasons; do
	grep -q "/$s/model.glb: 0 errors, 0 warnings," "$T/validator.log" ||
		fail "$s: the validator has errors or warnings"
done

if command -v assimp >/dev/null; then
	for s in $seasons; do
		for f in model.glb model.obj; do
			assimp info "$T/$s/$f" >"$T/assimp.log" 2>&1 ||
				{ cat "$T/assimp.log" >&2; fail "assimp info $s/$f"; }
			echo "assimp info $s/$f: $(grep -E '^(Meshes|Materials|Vertices|Faces):' "$T/assimp.log" | tr -s ' ' | tr '\n' ' ')"
		done
	done
else
	echo "assimp not installed: skipping the assimp check" >&2
fi

"$CHECK_SEASONS" "${dirs[@]}" || fail "check_seasons"
