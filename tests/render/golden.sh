#!/bin/sh
# golden.sh RENDER_SCENE IMGCMP SCENE GOLDEN_DIR OUT_DIR
# Renders SCENE (twice over, checking the frames are identical) and compares it with
# GOLDEN_DIR/SCENE.png. With EDAHA_UPDATE_GOLDEN=1 it replaces the golden instead.
set -eu
render=$1 imgcmp=$2 scene=$3 golden=$4/$3.png out=$5

mkdir -p "$out"
"$render" --twice "$scene" "$out/$scene.png"
if [ "${EDAHA_UPDATE_GOLDEN:-0}" = 1 ]; then
	cp "$out/$scene.png" "$golden"
	echo "golden.sh: updated $golden"
	exit 0
fi
exec "$imgcmp" --diff "$out/$scene-diff.png" "$golden" "$out/$scene.png"
