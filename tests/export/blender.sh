#!/bin/bash
# SPDX-License-Identifier: MIT
# blender.sh: the wind in model.glb in Blender (Debian 12's blender 3.4.1 and its bundled
# glTF importer, blender_wind.py): the demo in 3D and cherry, exported by the edaha binary
# (output.c), import with their 10 shape keys and the action "wind", and play: the crown's
# top moves, the trunk's foot does not. Then today's forest (issue 27): write_samples'
# forest-3-wind.glb (export_glb_forest) imports as three objects tree-N at their places,
# each with its shape keys and action over the one 8 s loop, each crown moving, each foot
# still (blender_forest.py). Paths come from meson's environment: EDAHA, DEMO,
# BLENDER_SCRIPT, WRITE_SAMPLES, BLENDER_FOREST_SCRIPT, EDAHA_GL_PRELOAD (ASan builds).
# Exit 77 (skipped) without blender.
set -uo pipefail
: "${EDAHA:?}" "${DEMO:?}" "${BLENDER_SCRIPT:?}" "${WRITE_SAMPLES:?}" "${BLENDER_FOREST_SCRIPT:?}"
if ! command -v blender >/dev/null 2>&1; then
	echo "blender not installed, skipping (Debian: apt-get install blender)" >&2
	exit 77
fi
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-blender.XXXXXX")
trap 'rm -rf "$T"' EXIT

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
run() {
	edaha --headless "$@" >"$T/log" 2>&1 || { cat "$T/log" >&2; fail "edaha $* exited $?"; }
}

run --out "$T/demo" --replay "$DEMO" --press 3d
run --out "$T/cherry" --press tpl-cherry
for d in demo cherry; do
	# Blender's own libraries are not built with ASan: no preload for it
	env -u LD_PRELOAD blender -b --factory-startup --python-exit-code 1 \
		--python "$BLENDER_SCRIPT" -- "$T/$d/model.glb" >"$T/$d.log" 2>&1 ||
		{ cat "$T/$d.log" >&2; fail "Blender: $d"; }
	grep '^edaha-wind: ' "$T/$d.log"
	grep -q "^edaha-wind: .*the foot 0$" "$T/$d.log" || { cat "$T/$d.log" >&2; fail "Blender: $d"; }
done

# the forest: three trees, one wind
mkdir "$T/forest" && "$WRITE_SAMPLES" "$T/forest" forest >"$T/forest.log" 2>&1 ||
	{ cat "$T/forest.log" >&2; fail "write_samples forest"; }
env -u LD_PRELOAD blender -b --factory-startup --python-exit-code 1 \
	--python "$BLENDER_FOREST_SCRIPT" -- "$T/forest/forest-3-wind.glb" >"$T/forest-blender.log" 2>&1 ||
	{ cat "$T/forest-blender.log" >&2; fail "Blender: forest"; }
grep '^edaha-forest: ' "$T/forest-blender.log"
grep -q '^edaha-forest: 3 trees, .*the foot 0$' "$T/forest-blender.log" ||
	{ cat "$T/forest-blender.log" >&2; fail "Blender: forest"; }
