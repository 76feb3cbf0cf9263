#!/bin/sh
# SPDX-License-Identifier: MIT
# validate_samples.sh khronos|assimp WRITE_SAMPLES OUTDIR [GLTF_VALIDATE]
# Writes the sample exports with write_samples, then checks every .glb with the Khronos
# validator or with `assimp info` (assimp also reads the OBJ). Exit 77: checker missing.
set -u

mode=$1 write_samples=$2 out=$3

case $mode in
assimp)
	if ! command -v assimp >/dev/null 2>&1; then
		echo "assimp not installed, skipping (Debian: apt-get install assimp-utils)" >&2
		exit 77
	fi
	;;
khronos) validator=$4 ;;
*)
	echo "usage: validate_samples.sh khronos|assimp WRITE_SAMPLES OUTDIR [GLTF_VALIDATE]" >&2
	exit 2
	;;
esac

rm -rf "$out" && mkdir -p "$out" || exit 1
"$write_samples" "$out" || exit 1

if [ "$mode" = khronos ]; then
	exec "$validator" "$out"/*.glb
fi

# Raw import (-r) of everything, plus the full post-processed import that applications
# use, except for empty.glb: assimp's post-processing rejects any scene without meshes
# ("No materials remaining"), valid or not.
status=0
check() {
	log="$1.assimp$2.log"
	if assimp info "$1" $2 >"$log" 2>&1; then
		echo "assimp info $1 $2: ok ($(grep -E '^(Meshes|Materials|Vertices|Faces):' "$log" | tr -s ' ' | tr '\n' ' '))"
	else
		echo "assimp info $1 $2: FAILED" >&2
		cat "$log" >&2
		status=1
	fi
}
for f in "$out"/*.glb "$out"/*.obj; do
	check "$f" -r
	[ "${f##*/}" = empty.glb ] || check "$f" ""
done
exit $status
