#!/bin/bash
# SPDX-License-Identifier: MIT
# edaha --headless --leaf NAME|FILE --opening T --out DIR (issue 15, seed 003), end to end:
# leaf.sh TEST. Paths come from meson's environment: EDAHA, IMGCMP, GLTF_VALIDATE, SRC (the
# source tree). With EDAHA_UPDATE_GOLDEN=1, `presets` writes tests/ori/golden/ instead of
# comparing: look at every picture before committing it.
set -uo pipefail
: "${EDAHA:?}" "${IMGCMP:?}" "${GLTF_VALIDATE:?}" "${SRC:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-leaf.XXXXXX")
trap 'rm -rf "$T"' EXIT
HERE=$SRC/tests/ori
GOLDEN=$SRC/tests/ori/golden
MALFORMED=$SRC/tests/ori/malformed
PRESETS="entire hop maple"
OPENINGS="0.1 0.5 1"
# small, so the repository can keep the pictures; square, as a leaf about is
SIZE=400x400
check() { python3 "$HERE/check_origami.py" "$@" || fail "check_origami.py $*"; }

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
# leaf OUT ARGS...: a leaf run that must succeed and write its three files
leaf() {
	local out=$1 rc=0 f
	shift
	edaha --headless --size "$SIZE" --out "$out" "$@" >"$T/stdout" 2>"$T/stderr" || rc=$?
	[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha --out $out $* exited $rc"; }
	for f in origami.json leaf.glb screen.png; do
		[ -s "$out/$f" ] || fail "edaha $*: no $f"
	done
	[ "$(ls "$out" | wc -l)" -eq 3 ] || fail "edaha $*: wrote $(ls "$out"), wanted three files"
}

# Every preset at 0.1, 0.5 and 1: the three files, leaf.glb through the Khronos validator,
# origami.json's keys and sizes, and the picture against its golden.
t_presets() {
	local p t name files=() fails=0 rc
	for p in $PRESETS; do
		for t in $OPENINGS; do
			name=$p-$t
			leaf "$T/$name" --leaf "$p" --opening "$t"
			check json "$T/$name/origami.json" "$t"
			check glb "$T/$name/leaf.glb"
			files+=("$T/$name/leaf.glb")
			if [ "${EDAHA_UPDATE_GOLDEN:-0}" = 1 ]; then
				mkdir -p "$GOLDEN"
				cp "$T/$name/screen.png" "$GOLDEN/$name.png"
				echo "leaf.sh: updated $GOLDEN/$name.png"
			elif ! "$IMGCMP" --diff "$T/$name-diff.png" "$GOLDEN/$name.png" "$T/$name/screen.png"; then
				echo "FAIL: $name differs from its golden $GOLDEN/$name.png" >&2
				fails=$((fails + 1))
			fi
		done
		# the opening moves the leaf, never its pattern
		cmp -s <(sed 's/"folded".*//' "$T/$p-0.1/origami.json") <(sed 's/"folded".*//' "$T/$p-1/origami.json") ||
			fail "$p: the opening changed the pattern"
		cmp -s "$T/$p-0.1/screen.png" "$T/$p-0.5/screen.png" && fail "$p: 0.1 and 0.5 look the same"
	done
	"$GLTF_VALIDATE" "${files[@]}" >"$T/validator.log"
	rc=$?
	grep -E 'errors|error:' "$T/validator.log"
	[ $rc -ne 77 ] || exit 77
	[ $rc -eq 0 ] || { cat "$T/validator.log"; fail "glTF validator"; }
	[ "$(grep -c ': 0 errors' "$T/validator.log")" -eq ${#files[@]} ] ||
		fail "the validator did not report on every file"
	# the same leaf twice, the same bytes
	leaf "$T/again" --leaf maple --opening 0.5
	for f in origami.json leaf.glb screen.png; do
		cmp -s "$T/maple-0.5/$f" "$T/again/$f" || fail "maple at 0.5 twice: $f differs"
	done
	# the checks can fail: a face with a vertex past the last, a row too few
	python3 - "$T/maple-0.5/origami.json" "$T/broken" <<-'PY'
	import json, sys
	doc = json.load(open(sys.argv[1]))
	doc["faces"][0][0] = len(doc["vertices"])
	json.dump(doc, open(sys.argv[2] + "-index.json", "w"))
	doc = json.load(open(sys.argv[1]))
	doc["opened"].pop()
	json.dump(doc, open(sys.argv[2] + "-rows.json", "w"))
	PY
	python3 "$HERE/check_origami.py" json "$T/broken-index.json" 0.5 2>/dev/null && fail "check passed a bad index"
	python3 "$HERE/check_origami.py" json "$T/broken-rows.json" 0.5 2>/dev/null && fail "check passed a missing row"
	[ "$fails" -eq 0 ] || fail "$fails pictures differ from their goldens"
	echo "leaf.sh: 3 presets at $OPENINGS: files, validator, origami.json and pictures"
}

# refused ARG LINE TEXT: edaha --leaf ARG exits 2 with one line on stderr, "edaha: ARG:LINE: "
# (LINE 0: "edaha: ARG: ") and TEXT after it, and writes nothing: --out is not made, or an
# empty one (every other time) stays empty
REFUSED=0
refused() {
	local file=$1 line=$2 text=$3 rc=0 want msg
	rm -rf "$T/out"
	REFUSED=$((REFUSED + 1))
	[ $((REFUSED % 2)) -eq 0 ] && mkdir "$T/out"
	edaha --headless --size 160x100 --out "$T/out" --leaf "$file" >"$T/stdout" 2>"$T/err" || rc=$?
	msg=$(cat "$T/err")
	[ $rc -eq 2 ] || { echo "$msg"; fail "$file: exit $rc, wanted 2"; }
	[ "$(wc -l <"$T/err")" -eq 1 ] || { echo "$msg"; fail "$file: not one line"; }
	[ ! -s "$T/stdout" ] || fail "$file: said $(cat "$T/stdout") on stdout"
	if [ "$line" -gt 0 ]; then want="edaha: $file:$line: "; else want="edaha: $file: "; fi
	case $msg in
	"$want"*"$text"*) ;;
	*) echo "$msg"; fail "$file: wanted \"$want...$text...\"" ;;
	esac
	[ ! -e "$T/out" ] || [ -z "$(ls -A "$T/out")" ] || fail "$file: wrote $(ls "$T/out")"
}

# Every malformed or impossible design of tests/ori/malformed/EXPECT (FILE LINE TEXT, as
# ori_read refuses it) refused through the command line alike; and whole-file faults.
t_malformed() {
	local file line text n=0
	[ -f "$MALFORMED/EXPECT" ] || fail "no $MALFORMED/EXPECT"
	while read -r file line text; do
		case $file in '' | '#'*) continue ;; esac
		[ -f "$MALFORMED/$file" ] || fail "EXPECT lists $file, which is not there"
		refused "$MALFORMED/$file" "$line" "$text"
		n=$((n + 1))
	done <"$MALFORMED/EXPECT"
	[ $n -gt 0 ] || fail "EXPECT lists no files"
	echo "leaf.sh: $n malformed designs refused with exit 2, FILE:LINE and nothing written"
	# a directory, a device, too large to read (no line)
	refused "$MALFORMED" 0 "Is a directory"
	refused /dev/null 0 "not a regular file"
	head -c 2000000 /dev/zero >"$T/2mb.yaml"
	refused "$T/2mb.yaml" 0 "file too large"
	# over what a good run wrote: nothing changes
	leaf "$T/good" --leaf maple
	cp -r "$T/good" "$T/before"
	file=$(grep -v '^#' "$MALFORMED/EXPECT" | grep -m1 . | cut -d' ' -f1)
	edaha --headless --out "$T/good" --leaf "$MALFORMED/$file" 2>/dev/null
	[ $? -eq 2 ] || fail "$file over a good run: not exit 2"
	diff -r "$T/before" "$T/good" >/dev/null || fail "$file over a good run changed its files"
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

# The options themselves: --opening's range and default, --leaf's company, an unknown
# name, --help.
t_usage() {
	local rest t
	for t in 1.5 -0.1 abc nan inf '' 0.5x; do
		usage --headless --out "$T/out" --leaf maple --opening "$t" -- "bad --opening \"$t\""
	done
	usage --leaf maple -- "--leaf needs --headless"
	usage --leaf maple --out "$T/out" -- "--out needs --headless"
	usage --headless --out "$T/out" --opening 0.5 -- "--opening is for a --leaf"
	usage --headless --out "$T/out" --leaf maple --generate "$SRC/presets/cherry.yaml" -- \
		"--generate does not go with --leaf"
	usage --headless --out "$T/out" --leaf maple --press 3d -- "does not go with --leaf"
	usage --headless --out "$T/out" --leaf maple --view 30 -- "--view does not go with --leaf"
	# a name that is no preset and no file: named, with the presets
	usage --headless --out "$T/out" --leaf mapel -- \
		'edaha: --leaf "mapel": no such leaf preset or file (presets: entire, hop, maple)'
	[ "$(wc -l <"$T/err")" -eq 1 ] || fail "an unknown preset: not one line"
	# the bounds are in
	leaf "$T/zero" --leaf maple --opening 0
	check json "$T/zero/origami.json" 0
	leaf "$T/one" --leaf entire --opening 1.0
	check json "$T/one/origami.json" 1
	# without --opening: the design's rest, as its file says
	rest=$(sed -n 's/^rest: *\([0-9.]*\).*/\1/p' "$SRC/presets/leaves/maple.yaml")
	[ -n "$rest" ] || fail "presets/leaves/maple.yaml has no rest"
	leaf "$T/rest" --leaf maple
	check json "$T/rest/origami.json" "$rest"
	leaf "$T/rest-given" --leaf maple --opening "$rest"
	cmp -s "$T/rest/origami.json" "$T/rest-given/origami.json" || fail "maple: no --opening is not --opening $rest"
	grep -q "maple at opening $rest" "$T/stdout" || fail "the run did not say the opening: $(cat "$T/stdout")"
	# a preset's file, read as a file, is the preset
	leaf "$T/file" --leaf "$SRC/presets/leaves/maple.yaml"
	cmp -s "$T/rest/leaf.glb" "$T/file/leaf.glb" || fail "presets/leaves/maple.yaml is not the maple preset"
	# --help tells both
	edaha --help >"$T/help" || fail "--help"
	grep -q -- '--leaf NAME|FILE' "$T/help" || fail "--help has no --leaf"
	grep -q -- '--opening T' "$T/help" || fail "--help has no --opening"
	grep -q "default: the design's rest opening" "$T/help" || fail "--help does not give --opening's default"
	echo "leaf.sh: usage errors, the bounds, the default opening and --help"
}

"t_$1"
