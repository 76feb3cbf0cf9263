#!/bin/bash
# SPDX-License-Identifier: MIT
# edaha --headless --support FILE.obj --vine NAME|FILE --plant X,Y,Z --out DIR (issue 16,
# seed 004), end to end: vine.sh TEST. Paths come from meson's environment: EDAHA, IMGCMP,
# GLTF_VALIDATE, SRC (the source tree). With EDAHA_UPDATE_GOLDEN=1, `pole` and `cross`
# write tests/vine/golden/ instead of comparing: look at every picture before committing it.
set -uo pipefail
: "${EDAHA:?}" "${IMGCMP:?}" "${GLTF_VALIDATE:?}" "${SRC:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-vine.XXXXXX")
trap 'rm -rf "$T"' EXIT
HERE=$SRC/tests/vine
GOLDEN=$SRC/tests/vine/golden
FILES="skeleton.json model.glb model.obj model.mtl screen.png"
# small, so the repository can keep the pictures; upright, as a pole is
SIZE=360x480
# on the ground beside the pole (R = 0.02 m): R + r and a little
PLANT=0.025,0,0

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
# vine OUT ARGS...: a vine run that must succeed and write its five files
vine() {
	local out=$1 rc=0 f
	shift
	edaha --headless --size "$SIZE" --out "$out" "$@" >"$T/stdout" 2>"$T/stderr" || rc=$?
	[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha --out $out $* exited $rc"; }
	for f in $FILES; do
		[ -s "$out/$f" ] || fail "edaha $*: no $f"
	done
	[ "$(ls "$out" | wc -l)" -eq 5 ] || fail "edaha $*: wrote $(ls "$out"), wanted five files"
}

# golden NAME OUT: OUT/screen.png against tests/vine/golden/NAME.png (or written there)
golden() {
	if [ "${EDAHA_UPDATE_GOLDEN:-0}" = 1 ]; then
		mkdir -p "$GOLDEN"
		cp "$2/screen.png" "$GOLDEN/$1.png"
		echo "vine.sh: updated $GOLDEN/$1.png"
	elif ! "$IMGCMP" --diff "$T/$1-diff.png" "$GOLDEN/$1.png" "$2/screen.png"; then
		fail "$1: screen.png differs from its golden $GOLDEN/$1.png"
	fi
}

# validate FILE...: the Khronos validator finds no error in any (77: it is not installed)
validate() {
	local rc=0
	"$GLTF_VALIDATE" "$@" >"$T/validator.log" || rc=$?
	[ $rc -ne 77 ] || exit 77
	[ $rc -eq 0 ] || { cat "$T/validator.log"; fail "glTF validator"; }
	[ "$(grep -c ': 0 errors' "$T/validator.log")" -eq $# ] ||
		{ cat "$T/validator.log"; fail "the validator did not pass every file"; }
}

# twice OUT ARGS...: the same run again writes the same bytes
twice() {
	local out=$1 f
	shift
	vine "$T/again" "$@"
	for f in $FILES; do
		cmp -s "$out/$f" "$T/again/$f" || fail "$* twice: $f differs"
	done
	rm -rf "$T/again"
}

# The pole: both ways of twining at R + r, the right way round; the picture, the GLB.
t_pole() {
	python3 "$HERE/support.py" pole "$T/pole.obj" || fail "support.py pole"
	vine "$T/mg" --support "$T/pole.obj" --vine morning-glory --plant "$PLANT"
	python3 "$HERE/check_vine.py" pole "$T/mg/skeleton.json" "$T/pole.obj" ||
		fail "morning-glory on the pole"
	vine "$T/def" --support "$T/pole.obj" --vine default --plant "$PLANT"
	python3 "$HERE/check_vine.py" pole "$T/def/skeleton.json" "$T/pole.obj" ||
		fail "default on the pole"
	grep -q '"twining":"right"' "$T/mg/skeleton.json" || fail "morning-glory does not twine right"
	grep -q '"twining":"left"' "$T/def/skeleton.json" || fail "default does not twine left"
	validate "$T/mg/model.glb" "$T/def/model.glb"
	twice "$T/mg" --support "$T/pole.obj" --vine morning-glory --plant "$PLANT"
	# the preset's file, read as a file, is the preset
	vine "$T/file" --support "$T/pole.obj" --vine "$SRC/presets/vines/morning-glory.yaml" \
		--plant "$PLANT"
	cmp -s "$T/mg/skeleton.json" "$T/file/skeleton.json" ||
		fail "presets/vines/morning-glory.yaml is not the morning-glory preset"
	golden pole "$T/mg"
	echo "vine.sh: pole: both twinings, the validator, twice the same, the picture"
}

# The cross: the vine climbs past the bar to the top.
t_cross() {
	python3 "$HERE/support.py" cross "$T/cross.obj" || fail "support.py cross"
	vine "$T/mg" --support "$T/cross.obj" --vine morning-glory --plant "$PLANT"
	python3 "$HERE/check_vine.py" cross "$T/mg/skeleton.json" "$T/cross.obj" ||
		fail "morning-glory on the cross"
	vine "$T/def" --support "$T/cross.obj" --vine default --plant "$PLANT"
	python3 "$HERE/check_vine.py" any "$T/def/skeleton.json" "$T/cross.obj" ||
		fail "default on the cross"
	validate "$T/mg/model.glb"
	twice "$T/mg" --support "$T/cross.obj" --vine morning-glory --plant "$PLANT"
	golden cross "$T/mg"
	echo "vine.sh: cross: past the bar, clear of it, the validator, twice the same, the picture"
}

# Issue 24's T (a pole of 1 cm, a bar as thick across its top): both twinings, planted
# beside the pole; the smoothed axes keep 0.95 r from it, outside it.
t_t() {
	python3 "$HERE/support.py" t "$T/t.obj" || fail "support.py t"
	vine "$T/mg" --support "$T/t.obj" --vine morning-glory --plant 0.013,0,0
	python3 "$HERE/check_vine.py" any "$T/mg/skeleton.json" "$T/t.obj" ||
		fail "morning-glory on the T"
	vine "$T/def" --support "$T/t.obj" --vine default --plant 0.013,0,0
	python3 "$HERE/check_vine.py" any "$T/def/skeleton.json" "$T/t.obj" ||
		fail "default on the T"
	echo "vine.sh: t: both twinings clear of the T"
}

# refused TEXT ARGS...: edaha --headless --support ... exits 2 with one line on stderr
# holding TEXT, and writes nothing: --out is not made, or an empty one (every other time)
# stays empty
REFUSED=0
refused() {
	local text=$1 rc=0 msg
	shift
	rm -rf "$T/out"
	REFUSED=$((REFUSED + 1))
	[ $((REFUSED % 2)) -eq 0 ] && mkdir "$T/out"
	edaha --headless --size 160x120 --out "$T/out" "$@" >"$T/stdout" 2>"$T/err" || rc=$?
	msg=$(cat "$T/err")
	[ $rc -eq 2 ] || { echo "$msg"; fail "$*: exit $rc, wanted 2"; }
	[ "$(wc -l <"$T/err")" -eq 1 ] || { echo "$msg"; fail "$*: not one line"; }
	[ ! -s "$T/stdout" ] || fail "$*: said $(cat "$T/stdout") on stdout"
	case $msg in
	*"$text"*) ;;
	*) echo "$msg"; fail "$*: wanted \"$text\"" ;;
	esac
	[ ! -e "$T/out" ] || [ -z "$(ls -A "$T/out")" ] || fail "$*: wrote $(ls "$T/out")"
}

# Bad supports and vine files: exit 2, one line naming the file, nothing written.
t_malformed() {
	local obj=$T/pole.obj
	python3 "$HERE/support.py" pole "$obj" || fail "support.py pole"
	: >"$T/empty.obj"
	printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' >"$T/nofaces.obj"
	printf 'v 0 0 0\nv 1 0 0\nv 1e39 1 0\nf 1 2 3\n' >"$T/huge.obj"
	printf 'v 0 0 0\nv 1 0 0\nv inf 1 0\nf 1 2 3\n' >"$T/inf.obj"
	printf 'solid pole\nendsolid pole\n' >"$T/pole.stl"
	printf 'edaha-vine: 1\ntwining: right\nleafs: 2\n' >"$T/bad.yaml"
	printf 'edaha-vine: 1\ninternode: 5\n' >"$T/range.yaml"
	refused "edaha: $T/missing.obj: No such file or directory" \
		--support "$T/missing.obj" --vine default --plant "$PLANT"
	refused "edaha: $T/pole.stl: not a Wavefront OBJ" --support "$T/pole.stl" --vine default \
		--plant "$PLANT"
	# a picture named .obj: assimp's OBJ reader says why
	cp "$SRC/tests/ori/golden/maple-1.png" "$T/picture.obj" || fail "no picture to copy"
	refused "edaha: $T/picture.obj: " --support "$T/picture.obj" --vine default --plant "$PLANT"
	refused "edaha: $T/empty.obj: not an OBJ file assimp can read" --support "$T/empty.obj" \
		--vine default --plant "$PLANT"
	refused "edaha: $T/nofaces.obj: no triangles" --support "$T/nofaces.obj" --vine default \
		--plant "$PLANT"
	refused "edaha: $T/huge.obj: a vertex with a coordinate that is not a finite number" \
		--support "$T/huge.obj" --vine default --plant "$PLANT"
	refused "edaha: $T/inf.obj: a vertex with a coordinate" --support "$T/inf.obj" \
		--vine default --plant "$PLANT"
	refused "edaha: $T: not a regular file" --support "$T" --vine default --plant "$PLANT"
	refused "edaha: $T/bad.yaml:3: " --support "$obj" --vine "$T/bad.yaml" --plant "$PLANT"
	refused "edaha: $T/range.yaml:2: " --support "$obj" --vine "$T/range.yaml" --plant "$PLANT"
	refused 'edaha: --vine "mornin-glory": no such vine preset or file (presets: default, morning-glory)' \
		--support "$obj" --vine mornin-glory --plant "$PLANT"
	# over what a good run wrote: nothing changes
	vine "$T/good" --support "$obj" --vine default --plant "$PLANT"
	cp -r "$T/good" "$T/before"
	edaha --headless --out "$T/good" --support "$T/empty.obj" --vine default --plant "$PLANT" \
		2>/dev/null
	[ $? -eq 2 ] || fail "an empty OBJ over a good run: not exit 2"
	diff -r "$T/before" "$T/good" >/dev/null || fail "an empty OBJ over a good run changed its files"
	echo "vine.sh: $REFUSED bad supports and vines refused with exit 2, one line, nothing written"
}

# usage ARGS... -- TEXT: edaha ARGS exits 2, says TEXT on stderr and writes nothing
usage() {
	local args=() rc=0
	while [ "$1" != -- ]; do
		args+=("$1")
		shift
	done
	rm -rf "$T/out"
	edaha "${args[@]}" >/dev/null 2>"$T/err" || rc=$?
	[ $rc -eq 2 ] || { cat "$T/err"; fail "edaha ${args[*]}: exit $rc, wanted 2"; }
	grep -qF -- "$2" "$T/err" || { cat "$T/err"; fail "edaha ${args[*]}: wanted \"$2\""; }
	[ ! -e "$T/out" ] || fail "edaha ${args[*]}: wrote $(ls "$T/out")"
}

# The options: --plant's three numbers, what goes with --support, --help.
t_usage() {
	local p obj=$T/pole.obj
	python3 "$HERE/support.py" pole "$obj" || fail "support.py pole"
	for p in 0,0 0,0,0,0 a,b,c 0,nan,0 inf,0,0 '' '0 0 0' 0,,0 1e999,0,0 0,0,0x; do
		usage --headless --out "$T/out" --support "$obj" --vine default --plant "$p" -- \
			"bad --plant \"$p\""
	done
	usage --support "$obj" --vine default --plant "$PLANT" -- "--support needs --headless"
	usage --headless --support "$obj" --vine default --plant "$PLANT" -- "needs --out DIR"
	usage --headless --out "$T/out" --support "$obj" --plant "$PLANT" -- \
		"--support needs --vine NAME|FILE and --plant X,Y,Z"
	usage --headless --out "$T/out" --support "$obj" --vine default -- \
		"--support needs --vine NAME|FILE and --plant X,Y,Z"
	usage --headless --out "$T/out" --vine default -- "--vine is for a --support"
	usage --headless --out "$T/out" --plant "$PLANT" -- "--plant is for a --support"
	usage --headless --out "$T/out" --support "$obj" --vine default --plant "$PLANT" \
		--leaf maple -- "--leaf does not go with --support"
	usage --headless --out "$T/out" --support "$obj" --vine default --plant "$PLANT" \
		--press 3d -- "does not go with --support"
	usage --headless --out "$T/out" --support "$obj" --vine default --plant "$PLANT" \
		--seed 3 -- "--seed does not go with --support"
	usage --headless --out "$T/out" --support "$obj" --vine default --plant "$PLANT" \
		--generate "$SRC/presets/cherry.yaml" -- "--generate does not go with --support"
	# --size does
	vine "$T/sized" --support "$obj" --vine default --plant "$PLANT"
	python3 - "$T/sized/screen.png" <<-'PY' || fail "--size not kept"
	import struct, sys
	w, h = struct.unpack(">II", open(sys.argv[1], "rb").read()[16:24])
	sys.exit(0 if (w, h) == (360, 480) else 1)
	PY
	edaha --help >"$T/help" || fail "--help"
	grep -q -- '--support FILE.obj' "$T/help" || fail "--help has no --support"
	grep -q -- '--vine NAME|FILE' "$T/help" || fail "--help has no --vine"
	grep -q -- '--plant X,Y,Z' "$T/help" || fail "--help has no --plant"
	echo "vine.sh: usage errors, --size and --help"
}

"t_$1"
