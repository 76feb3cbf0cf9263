#!/bin/bash
# SPDX-License-Identifier: MIT
# edaha --headless --skeleton FILE.json (issue 17), end to end: skeleton.sh TEST. Paths
# come from meson's environment: EDAHA, SRC (the source tree).
set -uo pipefail
: "${EDAHA:?}" "${SRC:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-skeleton.XXXXXX")
trap 'rm -rf "$T"' EXIT
HERE=$SRC/tests/doc/skeleton
DEMO=$SRC/tests/data/demo.edaha-trace
OUTPUTS="screen.png model.glb model.obj model.mtl skeleton.json drawing.edaha"

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
run() {
	local rc=0
	edaha --headless "$@" >"$T/stdout" 2>"$T/stderr" || rc=$?
	[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha $* exited $rc"; }
}

# A's branches in B: ids, parents, generations equal; parent_t, points, radii within 1e-6.
same_branches() {
	python3 - "$1" "$2" <<'EOF' || fail "$2's branches are not $1's"
import json, sys
a = json.load(open(sys.argv[1]))["branches"]
b = json.load(open(sys.argv[2]))["branches"]
assert len(a) == len(b) > 0, (len(a), len(b))
for x, y in zip(a, b):
    for k in ("id", "parent", "generation"):
        assert x[k] == y[k], (x["id"], k, x[k], y[k])
    assert abs(x["parent_t"] - y["parent_t"]) <= 1e-6, x["id"]
    assert len(x["points"]) == len(y["points"]) == len(y["radii"]), x["id"]
    for p, q in zip(x["points"], y["points"]):
        assert all(abs(u - v) <= 1e-6 for u, v in zip(p, q)), (x["id"], p, q)
    assert all(abs(u - v) <= 1e-6 for u, v in zip(x["radii"], y["radii"])), x["id"]
print(len(a), "branches the same")
EOF
}

t_roundtrip() {
	local f
	run --replay "$DEMO" --press 3d --out "$T/A"
	run --skeleton "$T/A/skeleton.json" --out "$T/B"
	for f in $OUTPUTS; do [ -s "$T/B/$f" ] || fail "no $f from --skeleton"; done
	same_branches "$T/A/skeleton.json" "$T/B/skeleton.json"
	grep -q '^import [0-9]* [0-9]*$' "$T/B/drawing.edaha" || fail "B/drawing.edaha has no import line"
	grep -q '^history 1 1$' "$T/B/drawing.edaha" || fail "B/drawing.edaha: not one op"
	# the drawing is the truth: loading it gives B again, byte for byte
	run --load "$T/B/drawing.edaha" --out "$T/C"
	for f in $OUTPUTS; do cmp -s "$T/B/$f" "$T/C/$f" || fail "$f differs after --load"; done
	# B's skeleton read again changes nothing; presses apply after the import (undo: empty)
	run --skeleton "$T/B/skeleton.json" --out "$T/D"
	for f in $OUTPUTS; do cmp -s "$T/B/$f" "$T/D/$f" || fail "$f differs on a second trip"; done
	run --skeleton "$T/A/skeleton.json" --press undo --out "$T/E"
	python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["branches"] == []' \
		"$T/E/skeleton.json" || fail "undo after --skeleton left branches"
	# a hand-written file (valid.json: two branches) reads too
	run --skeleton "$HERE/valid.json" --out "$T/F"
	grep -q '^import 100000 2$' "$T/F/drawing.edaha" || fail "valid.json: not two branches"
	echo "round trip: A's branches in B, B's drawing reloads to the same files"
}

t_malformed() {
	local dir=$HERE/malformed n=0 file line text rc want
	while read -r file line text; do
		case $file in '#'* | '') continue ;; esac
		edaha --headless --out "$T/m" --skeleton "$dir/$file" >/dev/null 2>"$T/err"; rc=$?
		[ $rc -eq 2 ] || { cat "$T/err"; fail "$file: exit $rc, wanted 2"; }
		want="edaha: $dir/$file:$line: "
		grep -qF "$want" "$T/err" || { cat "$T/err"; fail "$file: message does not start with $want"; }
		grep -qF "$text" "$T/err" || { cat "$T/err"; fail "$file: message does not say $text"; }
		[ ! -e "$T/m" ] || fail "$file: output written despite the error"
		n=$((n + 1))
	done <"$dir/EXPECT"
	[ $n -ge 15 ] || fail "only $n malformed files (want at least 15)"
	# a file that is not there, or a directory: exit 2 (the input's fault) or 1, never 0
	edaha --headless --out "$T/m" --skeleton "$T/none.json" 2>"$T/err"; rc=$?
	[ $rc -ne 0 ] && grep -qF "$T/none.json" "$T/err" || fail "a missing file: exit $rc"
	[ ! -e "$T/m" ] || fail "output written for a missing file"
	echo "$n malformed skeletons refused with exit 2 and file:line"
}

t_usage() {
	local args rc
	for args in "--skeleton $HERE/valid.json" \
		"--headless --out $T/u --skeleton $HERE/valid.json --load $T/x.edaha" \
		"--headless --out $T/u --skeleton $HERE/valid.json --generate $SRC/presets/cherry.yaml" \
		"--headless --out $T/u --skeleton $HERE/valid.json --leaf maple" \
		"--headless --out $T/u --skeleton $HERE/valid.json --support x.obj --vine default --plant 0,0,0" \
		"--headless --out $T/u --skeleton="; do
		# shellcheck disable=SC2086
		edaha $args >/dev/null 2>"$T/err"; rc=$?
		[ $rc -eq 2 ] || fail "edaha $args: exit $rc, wanted 2"
		grep -q -- "--skeleton\|needs a file" "$T/err" || { cat "$T/err"; fail "edaha $args: no word of --skeleton"; }
		[ ! -e "$T/u" ] || fail "edaha $args wrote output"
	done
	edaha --help >"$T/help" && grep -q -- "--skeleton FILE.json" "$T/help" || fail "--help does not mention --skeleton"
	echo "--skeleton's usage errors exit 2"
}

"t_$1"
