#!/bin/sh
# test_imgcmp.sh IMGCMP GOLDEN_DIR OUT_DIR: imgcmp's exit codes on the golden images.
set -u
imgcmp=$1 golden=$2 out=$3
fail=0

expect() {
	want=$1
	shift
	"$imgcmp" "$@" >/dev/null 2>&1
	got=$?
	if [ "$got" != "$want" ]; then
		echo "test_imgcmp.sh: imgcmp $*: exit $got, want $want"
		fail=1
	fi
}

# the goldens are being rewritten by the other tests right now
[ "${EDAHA_UPDATE_GOLDEN:-0}" = 1 ] && exit 77

mkdir -p "$out"
a=$golden/leaf.png b=$golden/eraser.png big=$golden/kiosk.png
head -c 100 "$a" > "$out/truncated.png"

expect 0 "$a" "$a"
expect 1 "$a" "$b"                         # same size, different pictures
expect 0 --max-fraction 1 "$a" "$b"        # ... unless any amount may differ
expect 0 --max-diff 255 "$a" "$b"          # ... or by any amount
expect 1 "$a" "$big"                       # sizes differ
expect 2 "$a" "$out/does-not-exist.png"
expect 2 "$out/truncated.png" "$a"
expect 2 "$a"                              # usage
expect 2 --max-diff 300 "$a" "$a"
expect 1 --diff "$out/imgcmp-diff.png" "$a" "$b"
[ -s "$out/imgcmp-diff.png" ] || { echo "test_imgcmp.sh: no diff image"; fail=1; }
expect 0 "$out/imgcmp-diff.png" "$out/imgcmp-diff.png"
exit $fail
