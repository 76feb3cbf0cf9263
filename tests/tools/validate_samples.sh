#!/bin/sh
# SPDX-License-Identifier: MIT
# validate_samples.sh khronos|assimp|summer WRITE_SAMPLES OUTDIR [GLTF_VALIDATE|SHA256S] [wind]
# Writes the sample exports with write_samples, then
# - khronos: checks every .glb with the Khronos validator: no error and no warning; with
#   `wind`, every NAME.glb has its NAME-wind.glb (the tree's sway, export_glb_wind), which
#   carries the animation "wind" unless NAME is the empty drawing;
# - assimp: reads every .glb and .obj with `assimp info` (the wind's too);
# - summer: checks that the summer samples are byte for byte what the exporters made
#   before trees had seasons (SHA256S, made at commit d67c552). Should the meshes change
#   on purpose (src/mesh/mesh.c, tests/tools/synth_tree.c), make it anew from that change's
#   write_samples, after checking that its exporters still give summer no COLOR_0 and the
#   one "leaves" material.
# Exit 77: checker missing.
set -u

mode=$1 write_samples=$2 out=$3

case $mode in
assimp)
	if ! command -v assimp >/dev/null 2>&1; then
		echo "assimp not installed, skipping (Debian: apt-get install assimp-utils)" >&2
		exit 77
	fi
	;;
khronos) validator=$4 wind=${5:-} ;;
summer) sums=$4 ;;
*)
	echo "usage: validate_samples.sh khronos|assimp|summer WRITE_SAMPLES OUTDIR [GLTF_VALIDATE|SHA256S]" >&2
	exit 2
	;;
esac

rm -rf "$out" && mkdir -p "$out" || exit 1
"$write_samples" "$out" || exit 1

if [ "$mode" = summer ]; then
	cd "$out" && exec sha256sum --strict -c "$sums"
fi

if [ "$mode" = khronos ] && [ "$wind" = wind ]; then
	for f in "$out"/*.glb; do
		case $f in *-wind.glb | *-wind-floats.glb) continue ;; esac
		w=${f%.glb}-wind.glb
		[ -f "$w" ] || { echo "validate_samples.sh: no ${w##*/}" >&2; exit 1; }
		[ "${f##*/}" = empty.glb ] && continue
		grep -aq '"animations":\[{"name":"wind",' "$w" ||
			{ echo "validate_samples.sh: ${w##*/} has no wind" >&2; exit 1; }
	done
fi
if [ "$mode" = khronos ]; then
	# gltf-validate fails on errors only; a warning fails here too
	"$validator" "$out"/*.glb >"$out/validator.log" 2>&1
	status=$?
	cat "$out/validator.log"
	[ $status -eq 0 ] || exit $status
	n=$(grep -c '\.glb: 0 errors, 0 warnings,' "$out/validator.log")
	set -- "$out"/*.glb
	want=$#
	if [ "$n" -ne "$want" ]; then
		echo "validate_samples.sh: $((want - n)) of $want files with errors or warnings" >&2
		exit 1
	fi
	exit 0
fi

# Raw import (-r) of everything, plus the full post-processed import that applications
# use, except for empty.glb and empty-wind.glb (the same): assimp's post-processing
# rejects any scene without meshes ("No materials remaining"), valid or not.
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
	case ${f##*/} in empty.glb | empty-wind.glb) ;; *) check "$f" "" ;; esac
done
exit $status
