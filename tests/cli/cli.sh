#!/bin/bash
# End-to-end tests of the edaha binary: cli.sh TEST. Paths come from meson's environment:
# EDAHA, IMGCMP, JSONCMP, GLTF_VALIDATE, SRC (the source tree's tests/ folder).
set -uo pipefail
: "${EDAHA:?}" "${SRC:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-cli.XXXXXX")
trap 'rm -rf "$T"' EXIT
DEMO=$SRC/data/demo.edaha-trace
ORBIT=$SRC/data/orbit.edaha-trace
# Sketches whose 3D trees have golden pictures from the front and from 90 degrees.
VIEW_SKETCHES="demo orbit lift-young lift-broadleaf lift-conifer lift-sine sketch-fan sketch-fan-outlines"
OUTPUTS="screen.png model.glb model.obj model.mtl skeleton.json drawing.edaha"

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
run() {
	local rc=0
	edaha --headless "$@" >"$T/stdout" 2>"$T/stderr" || rc=$?
	[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha $* exited $rc"; }
}
same_files() { # dir1 dir2 files...
	local a=$1 b=$2 f; shift 2
	for f in "$@"; do cmp -s "$a/$f" "$b/$f" || fail "$f differs between $a and $b"; done
}

t_help() {
	edaha --help >"$T/help" || fail "--help exited $?"
	for o in --headless --size --seed --out --replay --press --view --load --record --help \
		--idle --lang --config --stats --kiosk-frames --screenshot --window --kiosk --wind \
		--forest --forest-reset; do
		grep -q -- "$o" "$T/help" || fail "--help does not mention $o"
	done
	edaha --version | grep -q '^edaha ' || fail "--version"
}

t_usage() {
	local args
	for args in "--bogus" "--headless" "--headless --out $T/x --press nothing" \
		"--headless --out $T/x --size 10x10" "--headless --out $T/x --seed -1" "--replay $DEMO" "stray" \
		"--headless --out $T/x --view 400" "--headless --out $T/x --view 0,90" \
		"--headless --out $T/x --view 10,x" "--view 90" "--lang fr" "--idle 5" \
		"--headless --out $T/x --lang fr" "--headless --out $T/x --idle -1" \
		"--headless --out $T/x --idle nan" "--headless --out $T/x --idle soon" \
		"--headless --out $T/x --stats" "--headless --out $T/x --config /etc/edaha.conf" \
		"--window --kiosk" "--headless --out $T/x --window" "--headless --out $T/x --kiosk"; do
		# shellcheck disable=SC2086
		edaha $args >/dev/null 2>"$T/err"; rc=$?
		[ $rc -eq 2 ] || fail "edaha $args: exit $rc, wanted 2"
		grep -q "^edaha: " "$T/err" || fail "edaha $args: no message"
	done
	# the words of each option group's errors and of the checks after them, and which
	# conflict the checks name first (options.c)
	usage_says "--generate needs a file name" --headless --out "$T/x" --generate=
	usage_says "--wood needs a file name" --headless --out "$T/x" --wood=
	usage_says "--screenshot needs a file name" --screenshot=
	usage_says "--config needs a file name" --config=
	usage_says "--support needs a file name" --headless --out "$T/x" --support=
	usage_says "--leaf needs a leaf preset's name or a file name" --headless --out "$T/x" --leaf=
	usage_says "--vine needs a vine preset's name or a file name" --headless --out "$T/x" --vine=
	usage_says 'bad --kiosk-frames "0" (expected 1..1000000)' --kiosk-frames 0
	usage_says 'bad --kiosk-frames "1000001" (expected 1..1000000)' --kiosk-frames 1000001
	usage_says 'unknown or incomplete option "--size"' --headless --out "$T/x" --size
	usage_says 'unexpected argument "stray"' --headless --out "$T/x" stray
	usage_says "--wood needs --headless" --out "$T/x" --wood w.yaml
	usage_says "--wood is for a tree, not --leaf or --support" --headless --out "$T/x" --leaf maple \
		--wood w.yaml
	usage_says "--dump-voxels is for a tree, not --leaf or --support" --headless --out "$T/x" \
		--support s.obj --vine default --plant 0,0,0 --dump-voxels
	usage_says "--out needs --headless" --out "$T/x" --skeleton s.json
	usage_says "--skeleton needs --headless" --skeleton s.json --window
	usage_says "--load does not go with --skeleton" --headless --out "$T/x" --skeleton s.json \
		--load d.edaha --window
	usage_says "--window is not --headless" --headless --out "$T/x" --window --opening 0.5
	usage_says "--headless needs --out DIR" --headless --opening 0.5
	usage_says "--opening is for a --leaf" --headless --out "$T/x" --opening 0.5 --vine default
	[ ! -e "$T/x" ] || fail "a usage error wrote files"
}

# usage_says TEXT ARGS...: edaha ARGS exits 2 and its one line on stderr is "edaha: TEXT"
usage_says() {
	local want=$1 rc
	shift
	edaha "$@" >/dev/null 2>"$T/err"; rc=$?
	[ $rc -eq 2 ] || { cat "$T/err"; fail "edaha $*: exit $rc, wanted 2"; }
	[ "$(head -n 1 "$T/err")" = "edaha: $want" ] || { cat "$T/err"; fail "edaha $*: not \"$want\""; }
}

t_golden() {
	run --out "$T/o" --replay "$DEMO"
	for f in $OUTPUTS; do [ -s "$T/o/$f" ] || fail "missing $f"; done
	"$JSONCMP" --eps 1e-5 "$SRC/golden/demo-skeleton.json" "$T/o/skeleton.json" || fail "skeleton differs from golden"
	"$IMGCMP" "$SRC/golden/demo-screen.png" "$T/o/screen.png" || fail "screen differs from golden"
	# leaf mode with its suggestions: the thumbnail strip
	run --out "$T/leaf" --replay "$SRC/data/edit-leaf-suggest.edaha-trace"
	"$IMGCMP" "$SRC/golden/edit-leaf-suggest.png" "$T/leaf/screen.png" || fail "leaf suggestions differ from golden"
	# five branches fanned from the trunk's top stay five branches (sketching.md)
	local name
	for name in sketch-fan sketch-fan-outlines; do
		run --out "$T/$name" --replay "$SRC/data/$name.edaha-trace"
		"$IMGCMP" "$SRC/golden/$name-screen.png" "$T/$name/screen.png" || fail "$name: screen differs from golden"
	done
}

# The 3D trees from the front and turned by 90 degrees. The camera changes the picture
# only: the model and the drawing's history stay the same.
t_views() {
	local name trace
	for name in $VIEW_SKETCHES; do
		trace=$SRC/data/$name.edaha-trace
		[ -f "$trace" ] || trace=$SRC/data/$name
		run --out "$T/$name-front" --replay "$trace" --press 3d --view 0
		run --out "$T/$name-90" --replay "$trace" --press 3d --view 90
		same_files "$T/$name-front" "$T/$name-90" skeleton.json model.glb
		grep -q '^view 90 0$' "$T/$name-90/drawing.edaha" || fail "$name: the drawing does not keep the view"
		"$IMGCMP" "$SRC/golden/$name-3d-front.png" "$T/$name-front/screen.png" || fail "$name: front view differs"
		"$IMGCMP" "$SRC/golden/$name-3d-90.png" "$T/$name-90/screen.png" || fail "$name: 90 degree view differs"
		cmp -s "$T/$name-front/screen.png" "$T/$name-90/screen.png" && fail "$name: turning changed nothing"
	done
	# a sketch is not turned
	run --out "$T/flat" --replay "$DEMO" --view 90
	grep -q "not 3D" "$T/stderr" || fail "--view on a sketch: no note"
	"$IMGCMP" "$SRC/golden/demo-screen.png" "$T/flat/screen.png" || fail "--view turned a sketch"
}

# The labels in Japanese: another screen, the same drawing and model.
t_lang() {
	run --out "$T/en" --replay "$DEMO"
	run --out "$T/ja" --replay "$DEMO" --lang ja
	"$IMGCMP" "$SRC/golden/demo-screen-ja.png" "$T/ja/screen.png" || fail "Japanese labels differ from golden"
	cmp -s "$T/en/screen.png" "$T/ja/screen.png" && fail "--lang ja changed nothing"
	same_files "$T/en" "$T/ja" skeleton.json model.glb model.obj drawing.edaha
	run --out "$T/en2" --replay "$DEMO" --lang en
	same_files "$T/en" "$T/en2" screen.png
}

# --idle: the screen as the kiosk shows it that long after the last input. Nothing but the
# picture changes, and only when something on it is timed: the attract screen after 90 s
# (the same at any later moment), the turn into 3D during its first 2.4 s.
t_idle() {
	run --out "$T/now" --replay "$DEMO"
	run --out "$T/i0" --replay "$DEMO" --idle 0
	run --out "$T/i89" --replay "$DEMO" --idle 89.9
	same_files "$T/now" "$T/i0" $OUTPUTS
	same_files "$T/now" "$T/i89" $OUTPUTS
	run --out "$T/i120" --replay "$DEMO" --idle 120
	"$IMGCMP" "$SRC/golden/demo-attract.png" "$T/i120/screen.png" || fail "attract screen differs from golden"
	same_files "$T/now" "$T/i120" skeleton.json model.glb model.obj drawing.edaha
	run --out "$T/i90" --replay "$DEMO" --idle 90
	run --out "$T/iday" --replay "$DEMO" --idle 86400
	same_files "$T/i120" "$T/i90" screen.png
	same_files "$T/i120" "$T/iday" screen.png
	run --out "$T/ja" --replay "$DEMO" --idle 120 --lang ja
	"$IMGCMP" "$SRC/golden/demo-attract-ja.png" "$T/ja/screen.png" || fail "Japanese attract screen differs from golden"
	# with nothing drawn the kiosk invites as well
	run --out "$T/empty"
	run --out "$T/empty-idle" --idle 100
	"$IMGCMP" --max-fraction 0.1 "$T/empty/screen.png" "$T/empty-idle/screen.png" &&
		fail "no attract screen over an empty drawing"
	# the turn into 3D: a step of it half a second in, settled after
	run --out "$T/3d" --replay "$DEMO" --press 3d
	run --out "$T/3d-turning" --replay "$DEMO" --press 3d --idle 0.5
	run --out "$T/3d-settled" --replay "$DEMO" --press 3d --idle 10
	cmp -s "$T/3d/screen.png" "$T/3d-turning/screen.png" && fail "--idle 0.5 after 3d shows no turn"
	same_files "$T/3d" "$T/3d-settled" $OUTPUTS
}

t_determinism() {
	local wacom=$SRC/data/wacom-intuos-pro-m.yml
	# different heap garbage and rasteriser threads must not change a byte
	MALLOC_PERTURB_=17 LP_NUM_THREADS=0 run --out "$T/a" --seed 9 --replay "$DEMO" --press leaf --replay "$wacom" --press 3d
	MALLOC_PERTURB_=201 LP_NUM_THREADS=2 run --out "$T/b" --seed 9 --replay "$DEMO" --press leaf --replay "$wacom" --press 3d
	# shellcheck disable=SC2086
	same_files "$T/a" "$T/b" $OUTPUTS
	# turned with the pen and drawn on
	MALLOC_PERTURB_=17 LP_NUM_THREADS=0 run --out "$T/c" --seed 3 --replay "$ORBIT"
	MALLOC_PERTURB_=201 LP_NUM_THREADS=2 run --out "$T/d" --seed 3 --replay "$ORBIT"
	# shellcheck disable=SC2086
	same_files "$T/c" "$T/d" $OUTPUTS
}

t_undo_redo() {
	run --out "$T/a" --replay "$DEMO"
	run --out "$T/b" --replay "$DEMO" --press undo --press undo --press redo --press redo
	same_files "$T/a" "$T/b" skeleton.json model.glb model.obj screen.png
	run --out "$T/c" --replay "$DEMO" --press undo
	cmp -s "$T/a/skeleton.json" "$T/c/skeleton.json" && fail "undo changed nothing"
	run --out "$T/d" --replay "$DEMO" --press new
	grep -q '"branches":\[\]' <(tr -d ' \n' <"$T/d/skeleton.json") || fail "new did not clear"
	run --out "$T/e" --replay "$DEMO" --press new --press undo
	same_files "$T/a" "$T/e" skeleton.json model.glb
}

t_load() {
	# split the demo after its fourth stroke; part two keeps the header lines
	local cut
	cut=$(grep -n ' proximity-out ' "$DEMO" | sed -n 4p | cut -d: -f1)
	[ -n "$cut" ] || fail "demo trace has fewer than 4 strokes"
	head -n "$cut" "$DEMO" >"$T/p1.trace"
	{ grep -E '^(edaha-trace|screen) ' "$DEMO"; tail -n +"$((cut + 1))" "$DEMO"; } >"$T/p2.trace"
	run --out "$T/one" --replay "$T/p1.trace" --replay "$T/p2.trace"
	run --out "$T/half" --replay "$T/p1.trace"
	run --out "$T/two" --load "$T/half/drawing.edaha" --replay "$T/p2.trace"
	same_files "$T/one" "$T/two" skeleton.json model.glb model.obj screen.png
	# a loaded drawing saves back unchanged
	run --out "$T/again" --load "$T/half/drawing.edaha"
	same_files "$T/half" "$T/again" drawing.edaha skeleton.json model.glb
	# the same across a turned tree: split after the drag that turns it, so the second
	# part draws on the turned tree the drawing brings back
	cut=$(grep -n ' proximity-out ' "$ORBIT" | sed -n 6p | cut -d: -f1)
	head -n "$cut" "$ORBIT" >"$T/o1.trace"
	{ grep -E '^(edaha-trace|screen) ' "$ORBIT"; tail -n +"$((cut + 1))" "$ORBIT"; } >"$T/o2.trace"
	run --out "$T/ohalf" --replay "$T/o1.trace"
	grep -q '^view ' "$T/ohalf/drawing.edaha" || fail "the turned view is not saved"
	run --out "$T/otwo" --load "$T/ohalf/drawing.edaha" --replay "$T/o2.trace"
	run --out "$T/oone" --replay "$ORBIT"
	same_files "$T/oone" "$T/otwo" skeleton.json model.glb model.obj screen.png drawing.edaha
}

t_record() {
	local wacom=$SRC/data/wacom-intuos-pro-m.yml
	run --out "$T/a" --replay "$wacom" --press undo --record "$T/rec.trace"
	head -n1 "$T/rec.trace" | grep -q '^edaha-trace 1' || fail "recording has no header"
	run --out "$T/b" --replay "$T/rec.trace"
	same_files "$T/a" "$T/b" skeleton.json model.glb screen.png
	run --out "$T/c" --replay "$ORBIT" --record "$T/orbit.trace"
	run --out "$T/d" --replay "$T/orbit.trace"
	same_files "$T/c" "$T/d" skeleton.json model.glb screen.png drawing.edaha
}

# Issue 15: leaf-maple pressed, then a recorded leaf arrangement: the leaves it places are
# maple leaves in skeleton.json, the drawing holds the choice, the export validates, and
# the drawing replays to the same files.
t_origami() {
	local n
	run --out "$T/o" --press leaf-maple --replay "$SRC/data/edit-leaf-whorl.edaha-trace"
	n=$(grep -o '"kind":"maple"' "$T/o/skeleton.json" | wc -l)
	[ "$n" -ge 2 ] || fail "only $n maple leaves in skeleton.json"
	grep -q '"kind":"drawn"\|"kind":"hop"' "$T/o/skeleton.json" && fail "unexpected leaf kinds"
	grep -q '^leaftype [0-9]* maple$' "$T/o/drawing.edaha" || fail "no leaftype op in the drawing"
	"$GLTF_VALIDATE" "$T/o/model.glb" || fail "the origami export does not validate"
	run --out "$T/o2" --load "$T/o/drawing.edaha"
	same_files "$T/o" "$T/o2" model.glb model.obj skeleton.json drawing.edaha
	echo "$n maple leaves placed, exported and replayed"
	# a propagated tree with each lobed preset: golden pictures (EDAHA_UPDATE_GOLDEN=1
	# writes them)
	for k in maple hop; do
		run --out "$T/p-$k" --press leaf-$k --replay "$SRC/data/edit-propagate-count.edaha-trace"
		grep -q "\"kind\":\"$k\"" "$T/p-$k/skeleton.json" || fail "no $k leaves propagated"
		if [ -n "${EDAHA_UPDATE_GOLDEN:-}" ]; then
			cp "$T/p-$k/screen.png" "$SRC/golden/origami-propagate-$k.png"
		else
			"$IMGCMP" "$SRC/golden/origami-propagate-$k.png" "$T/p-$k/screen.png" ||
				fail "the propagated $k leaves differ from golden"
		fi
	done
	# the propagated leaves unfold over a second after the last event, by its time: in
	# the bud just after, the same picture for the same moment, at rest once it is over
	for s in 0.05 0.05b 0.5 1.5; do
		run --out "$T/u-$s" --press leaf-maple --idle "${s%b}" \
			--replay "$SRC/data/edit-propagate-count.edaha-trace"
	done
	cmp -s "$T/u-0.05/screen.png" "$T/u-0.05b/screen.png" || fail "unfolding is not repeatable"
	cmp -s "$T/u-0.05/screen.png" "$T/u-0.5/screen.png" && fail "the leaves do not unfold"
	cmp -s "$T/u-0.5/screen.png" "$T/u-1.5/screen.png" && fail "the leaves still unfold at 1.5 s"
	"$IMGCMP" "$T/u-1.5/screen.png" "$T/p-maple/screen.png" ||
		fail "the leaves are not at rest 1.5 s after"
	same_files "$T/u-0.05" "$T/p-maple" skeleton.json model.glb
}

# The vine mode (issue 16): the demo's tree, 3D, the vine button and a tap at its foot
# plant a vine that is in the drawing, replays from it and exports; on screen it grows
# by the events' time (--idle), and the files do not depend on when they are written.
t_vine() {
	local tap="$SRC/data/vine-tap.edaha-trace"

	run --out "$T/v" --replay "$DEMO" --press 3d --press vine --replay "$tap" --view 30,15
	grep -q '^vine [0-9]* ' "$T/v/drawing.edaha" || fail "no vine op in the drawing"
	grep -q '"version":2' "$T/v/skeleton.json" || fail "skeleton.json is not version 2"
	grep -q '"vines":\[{' "$T/v/skeleton.json" || fail "no vine in skeleton.json"
	grep -q '^o vine$' "$T/v/model.obj" || fail "no vine in model.obj"
	"$GLTF_VALIDATE" "$T/v/model.glb" || fail "the export with a vine does not validate"
	run --out "$T/v2" --load "$T/v/drawing.edaha" --view 30,15
	same_files "$T/v" "$T/v2" model.glb model.obj skeleton.json drawing.edaha
	# entering the mode says where to tap (in the mode's colour, an arrow to the ground)
	run --out "$T/h" --replay "$DEMO" --press 3d --press vine --idle 1
	if [ -n "${EDAHA_UPDATE_GOLDEN:-}" ]; then
		cp "$T/v/screen.png" "$SRC/golden/vine-demo.png"
		cp "$T/h/screen.png" "$SRC/golden/vine-hint.png"
	else
		"$IMGCMP" "$SRC/golden/vine-demo.png" "$T/v/screen.png" ||
			fail "the vine on the demo tree differs from golden"
		"$IMGCMP" "$SRC/golden/vine-hint.png" "$T/h/screen.png" ||
			fail "the vine mode's hint differs from golden"
	fi
	for s in 0.3 0.3b 2 30; do
		run --out "$T/i-$s" --replay "$DEMO" --press 3d --press vine --replay "$tap" \
			--view 30,15 --idle "${s%b}"
	done
	cmp -s "$T/i-0.3/screen.png" "$T/i-0.3b/screen.png" || fail "growth is not repeatable"
	cmp -s "$T/i-0.3/screen.png" "$T/i-2/screen.png" && fail "the vine does not grow"
	"$IMGCMP" "$T/i-30/screen.png" "$T/v/screen.png" || fail "the vine is not grown after 30 s"
	same_files "$T/i-0.3" "$T/v" skeleton.json model.glb model.obj
	echo "a vine planted, replayed, grown on screen and exported"
}

# Issue 26: a tree made 3D grows in from its foot, by the events' time: --idle T shows the
# moment T s after the last input (the 3D press's release), the same picture every time; the
# files are the settled tree's; without --idle the screen is the settled tree's, as a run
# long after; a button pressed after it finishes the growth at once; a loaded 3D drawing
# grows in too, its vine climbing after it.
t_grow_in() {
	run --out "$T/g" --replay "$DEMO" --press 3d
	for s in 0.2 1.8 1.8b 30; do
		run --out "$T/g-$s" --replay "$DEMO" --press 3d --idle "${s%b}"
	done
	cmp -s "$T/g-1.8/screen.png" "$T/g-1.8b/screen.png" || fail "growing in is not repeatable"
	cmp -s "$T/g-0.2/screen.png" "$T/g-1.8/screen.png" && fail "the tree does not grow"
	cmp -s "$T/g/screen.png" "$T/g-1.8/screen.png" && fail "no growth 1.8 s after 3d"
	same_files "$T/g" "$T/g-30" $OUTPUTS
	same_files "$T/g" "$T/g-1.8" skeleton.json model.glb model.obj drawing.edaha
	"$IMGCMP" "$SRC/golden/demo-3d-front.png" "$T/g/screen.png" ||
		fail "the settled 3D tree differs from golden"
	if [ -n "${EDAHA_UPDATE_GOLDEN:-}" ]; then
		cp "$T/g-1.8/screen.png" "$SRC/golden/demo-grow.png"
	else
		"$IMGCMP" "$SRC/golden/demo-grow.png" "$T/g-1.8/screen.png" ||
			fail "the growing demo tree differs from golden"
	fi
	# a button put down finishes it: the same as with no --idle
	run --out "$T/f" --replay "$DEMO" --press 3d --press view --idle 1.2
	run --out "$T/f0" --replay "$DEMO" --press 3d --press view
	same_files "$T/f" "$T/f0" screen.png
	# a loaded 3D drawing grows in from the start of the run
	run --out "$T/l" --load "$T/g/drawing.edaha" --idle 0.5
	run --out "$T/l0" --load "$T/g/drawing.edaha"
	cmp -s "$T/l/screen.png" "$T/l0/screen.png" && fail "a loaded 3D drawing does not grow in"
	same_files "$T/l" "$T/l0" skeleton.json model.glb model.obj drawing.edaha
	# its vines climb after it: none while it grows (the same picture as without the vine),
	# the last one climbing after, grown in the end
	run --out "$T/v" --replay "$DEMO" --press 3d --press vine --replay "$SRC/data/vine-tap.edaha-trace"
	run --out "$T/l-2.5" --load "$T/g/drawing.edaha" --idle 2.5
	run --out "$T/v-2.5" --load "$T/v/drawing.edaha" --idle 2.5
	run --out "$T/v-4" --load "$T/v/drawing.edaha" --idle 4
	run --out "$T/v-30" --load "$T/v/drawing.edaha" --idle 30
	run --out "$T/v-settled" --load "$T/v/drawing.edaha"
	same_files "$T/l-2.5" "$T/v-2.5" screen.png
	cmp -s "$T/v-4/screen.png" "$T/v-30/screen.png" && fail "the vine does not climb after the tree"
	same_files "$T/v-30" "$T/v-settled" screen.png
	echo "a tree growing in: its moments repeatable, settled without --idle, finished by a press"
}

t_exports_valid() {
	run --out "$T/demo" --replay "$DEMO"
	run --out "$T/demo3d" --replay "$DEMO" --press 3d
	run --out "$T/orbit" --replay "$ORBIT"
	run --out "$T/wacom" --replay "$SRC/data/wacom-intuos-pro-m.yml"
	run --out "$T/empty"
	"$GLTF_VALIDATE" "$T/demo/model.glb" "$T/demo3d/model.glb" "$T/orbit/model.glb" "$T/wacom/model.glb" \
		"$T/empty/model.glb" ||
		fail "glTF validator"
	if command -v assimp >/dev/null; then
		for f in demo/model.glb demo/model.obj demo3d/model.glb wacom/model.glb; do
			assimp info "$T/$f" >"$T/assimp.log" 2>&1 || { cat "$T/assimp.log"; fail "assimp info $f"; }
		done
	else
		echo "assimp not installed: skipping the assimp check" >&2
	fi
}

t_hostile() {
	# valid but extreme input: pens far off the screen, subnormal numbers, huge strokes.
	# edaha bounds the work, and every drawing it writes loads back to the same tree.
	local f opt name
	for f in "$SRC"/hostile/*; do
		case $f in *.edaha) opt=--load ;; *) opt=--replay ;; esac
		name=$(basename "$f")
		run --out "$T/$name" "$opt" "$f"
		[ "$(stat -c %s "$T/$name/model.obj")" -lt 20000000 ] || fail "$name: model.obj over 20 MB"
		run --out "$T/$name.again" --load "$T/$name/drawing.edaha"
		same_files "$T/$name" "$T/$name.again" skeleton.json model.glb drawing.edaha
	done
}

# Today's forest (issue 27, docs/forest.md): --forest DIR plants every drawing in DIR in
# name order, numbered 1, 2, 3, ... (a 2D sketch lifted, generated and edited trees), skips
# a damaged and a hostile file by name (forest.json's "skipped", no number taken), the
# newest 40 of 45 stand, numbers kept; no two trunks closer than the sum of a third of
# their crowns; the same run twice the same bytes. --forest-reset writes the day file.
t_forest() {
	local d=$T/drawings i
	mkdir -p "$d"
	run --out "$T/sketch" --replay "$DEMO"
	run --out "$T/lifted" --replay "$DEMO" --press 3d
	run --out "$T/cherry" --press tpl-cherry
	cp "$T/sketch/drawing.edaha" "$d/a-sketch.edaha"
	cp "$T/lifted/drawing.edaha" "$d/b-lifted.edaha"
	cp "$T/cherry/drawing.edaha" "$d/c-cherry.edaha"
	cp "$SRC/gen/malformed/drawing-no-version.edaha" "$d/d-damaged.edaha"
	printf 'edaha-drawing 7\nseed 1\n<script>alert(1)</script>\n' >"$d/e-<script>.edaha"
	cp "$SRC/fuzz/corpus/doc/new.edaha" "$d/f-empty.edaha"
	echo "not a drawing" >"$d/notes.txt"
	run --forest "$d" --out "$T/f"
	python3 - "$T/f/forest.json" <<'PY' || fail "forest.json of three trees"
import json, sys
f = json.load(open(sys.argv[1]))
assert f["format"] == "edaha-forest" and f["version"] == 1, f
trees = f["trees"]
assert [t["number"] for t in trees] == [1, 2, 3], trees
assert [t["file"] for t in trees] == ["a-sketch.edaha", "b-lifted.edaha", "c-cherry.edaha"], trees
for t in trees:
    assert t["height"] > 1 and t["crown_width"] > 0.5 and t["branches"] > 0, t
    assert t["position"][1] == 0, t
skipped = {s["file"]: s["why"] for s in f["skipped"]}
assert set(skipped) == {"d-damaged.edaha", "e-<script>.edaha", "f-empty.edaha"}, skipped
assert "no tree" in skipped["f-empty.edaha"], skipped
assert all(w for w in skipped.values()), skipped
PY
	grep -q "skipped.*d-damaged.edaha" "$T/stderr" || fail "the damaged file is not named on stderr"
	# screen.png: the attract screen's forest, the camera travelling (another moment,
	# another picture; the same moment, the same bytes)
	run --forest "$d" --out "$T/f30" --idle 30
	cmp -s "$T/f/screen.png" "$T/f30/screen.png" && fail "the forest's camera does not travel"
	same_files "$T/f" "$T/f30" forest.json forest.glb
	# --idle 2: the newest tree (cherry, No. 3) joined at the attract screen's moment 0,
	# two seconds into its growth (its trunk and limbs, no twigs or leaves yet)
	run --forest "$d" --out "$T/fg" --idle 2
	cmp -s "$T/f30/screen.png" "$T/fg/screen.png" && fail "--idle 2 is --idle 30"
	# forest.glb: a node a tree, named by its number, one wind; the Khronos validator
	for i in 1 2 3; do
		grep -aq "\"name\":\"tree-$i\"" "$T/f/forest.glb" || fail "forest.glb has no node tree-$i"
	done
	grep -aq '"animations":\[{"name":"wind",' "$T/f/forest.glb" || fail "forest.glb has no wind"
	"$GLTF_VALIDATE" "$T/f/forest.glb" >"$T/validate.log" || { cat "$T/validate.log"; fail "forest.glb"; }
	grep -q ': 0 errors, 0 warnings,' "$T/validate.log" || { cat "$T/validate.log"; fail "forest.glb warnings"; }
	run --forest "$d" --out "$T/f2"
	same_files "$T/f" "$T/f2" forest.json forest.glb screen.png
	# 45 drawings of the kinds visitors make (a sketch made 3D, templates, a grown tree
	# with a vine): the newest 40 stand, numbered 6..45
	run --out "$T/zelkova" --press tpl-zelkova
	run --out "$T/palm" --press tpl-palm
	run --out "$T/grown" --replay "$DEMO" --press 3d --press grow --press vine \
		--replay "$SRC/data/vine-tap.edaha-trace"
	mkdir -p "$T/many"
	local kinds=(lifted cherry zelkova palm grown)
	for i in $(seq -w 1 45); do
		cp "$T/${kinds[$((10#$i % 5))]}/drawing.edaha" "$T/many/tree-$i.edaha"
	done
	run --forest "$T/many" --out "$T/m" --idle 20
	python3 - "$T/m/forest.json" <<'PY' || fail "the newest 40 of 45"
import itertools, json, math, sys
trees = json.load(open(sys.argv[1]))["trees"]
assert [t["number"] for t in trees] == list(range(6, 46)), [t["number"] for t in trees]
assert trees[0]["file"] == "tree-06.edaha" and trees[-1]["file"] == "tree-45.edaha"
worst = min(math.dist(a["position"], b["position"]) / ((a["crown_width"] + b["crown_width"]) / 3)
            for a, b in itertools.combinations(trees, 2))
assert worst >= 1.0, worst
print("forest of 45: the newest 40 stand; the closest trunks %.2f times the sum of a third of their crowns" % worst)
PY
	if [ -n "${EDAHA_UPDATE_GOLDEN:-}" ]; then
		cp "$T/f/screen.png" "$SRC/golden/forest-3.png"
		cp "$T/fg/screen.png" "$SRC/golden/forest-3-growing.png"
		cp "$T/m/screen.png" "$SRC/golden/forest-40.png"
	else
		"$IMGCMP" "$SRC/golden/forest-3.png" "$T/f/screen.png" ||
			fail "the forest of three differs from golden"
		"$IMGCMP" "$SRC/golden/forest-3-growing.png" "$T/fg/screen.png" ||
			fail "the forest of three, its newest growing in, differs from golden"
		"$IMGCMP" "$SRC/golden/forest-40.png" "$T/m/screen.png" ||
			fail "the forest of forty differs from golden"
	fi
	# an unreadable directory: usage's exit 2, nothing written
	edaha --headless --forest "$T/none" --out "$T/x" >/dev/null 2>"$T/err" && fail "--forest of nothing"
	[ ! -e "$T/x/forest.json" ] && [ ! -e "$T/x/forest.glb" ] && [ ! -e "$T/x/screen.png" ] ||
		fail "a failed --forest wrote files"
	usage_says "--forest needs --headless" --forest "$d"
	usage_says "--load does not go with --forest (only --out, --idle, --size, --lang and --wind do)" \
		--headless --out "$T/x" --forest "$d" --load a.edaha
	# --forest-reset: a new day in the configuration's state directory
	mkdir -p "$T/state/archive"
	cp "$T/lifted/drawing.edaha" "$T/state/archive/drawing-000041.edaha"
	printf 'kiosk:\n  state_dir: %s\n' "$T/state" >"$T/reset.conf"
	edaha --forest-reset --config "$T/reset.conf" >"$T/out" 2>&1 || { cat "$T/out"; fail "--forest-reset"; }
	grep -q '^edaha-forest-day: 1$' "$T/state/forest-day" && grep -q '^first: 42$' "$T/state/forest-day" ||
		{ cat "$T/state/forest-day"; fail "--forest-reset: not a new day from No. 42"; }
	usage_says "--forest-reset goes with --config only" --forest-reset --stats
	echo "a forest of three drawings (forest.json, forest.glb, screen.png; the newest growing in at --idle 2), three skipped by name; the newest 40 of 45; --forest-reset"
}

# The wind on the screen (issue 26): with --wind S, --idle T shows the tree swaying at that
# moment (the same picture every time, another a moment later); without --idle the tree at
# rest, today's screen; the attract screen in a breeze leaves the tree in sight (a band at
# the canvas's foot), swaying behind it. Goldens of a moment of wind and of that attract.
t_wind_screen() {
	local s
	run --out "$T/rest" --replay "$DEMO" --press 3d
	run --out "$T/still" --replay "$DEMO" --press 3d --wind 0 --idle 10
	run --out "$T/wr" --replay "$DEMO" --press 3d --wind 0.35
	same_files "$T/rest" "$T/still" $OUTPUTS
	same_files "$T/rest" "$T/wr" screen.png drawing.edaha model.obj
	for s in 10 10b 10.5 120 120.5; do
		run --out "$T/w-$s" --replay "$DEMO" --press 3d --wind 0.35 --idle "${s%b}"
	done
	cmp -s "$T/w-10/screen.png" "$T/w-10b/screen.png" || fail "the wind is not repeatable"
	cmp -s "$T/w-10/screen.png" "$T/still/screen.png" && fail "the tree does not sway"
	cmp -s "$T/w-10/screen.png" "$T/w-10.5/screen.png" && fail "the tree holds still for 0.5 s"
	# the moment of wind shows the tree as at rest, bent a little: close to the still screen
	"$IMGCMP" --max-diff 64 --max-fraction 0.03 "$T/still/screen.png" "$T/w-10/screen.png" ||
		fail "the swaying tree is far from the tree at rest"
	"$IMGCMP" --max-diff 8 --max-fraction 0.002 "$T/w-120/screen.png" "$T/w-120.5/screen.png" \
		>/dev/null && fail "the tree holds still under the attract screen"
	same_files "$T/w-10" "$T/w-120" drawing.edaha model.glb skeleton.json
	if [ -n "${EDAHA_UPDATE_GOLDEN:-}" ]; then
		cp "$T/w-10/screen.png" "$SRC/golden/demo-wind.png"
		cp "$T/w-120/screen.png" "$SRC/golden/demo-attract-wind.png"
	else
		"$IMGCMP" "$SRC/golden/demo-wind.png" "$T/w-10/screen.png" ||
			fail "the demo tree in the wind differs from golden"
		"$IMGCMP" "$SRC/golden/demo-attract-wind.png" "$T/w-120/screen.png" ||
			fail "the attract screen in the wind differs from golden"
	fi
	echo "the tree sways on the screen with --wind, repeatably, under the attract screen too"
}

# The wind in the files (issue 26, docs/living-trees.md): model.glb's animation "wind" at
# the breeze without --wind and with --wind 0 (a still screen), at S with --wind S, the
# 2D sketch's too, none for an empty drawing; skeleton.json's "wind"; model.obj and the
# drawing the same whatever the wind; the Khronos validator; --wind's usage errors.
t_wind() {
	local d
	run --out "$T/w" --replay "$DEMO" --press 3d
	run --out "$T/w0" --replay "$DEMO" --press 3d --wind 0
	run --out "$T/w8" --replay "$DEMO" --press 3d --wind 0.8
	same_files "$T/w" "$T/w0" model.glb model.obj model.mtl skeleton.json drawing.edaha screen.png
	same_files "$T/w" "$T/w8" model.obj model.mtl drawing.edaha
	cmp -s "$T/w/model.glb" "$T/w8/model.glb" && fail "--wind 0.8 exported the breeze"
	for d in w w8; do
		grep -aq '"animations":\[{"name":"wind",' "$T/$d/model.glb" || fail "$d: no wind in model.glb"
		grep -aq '"extensionsRequired":\["KHR_mesh_quantization"\]' "$T/$d/model.glb" ||
			fail "$d: model.glb's targets are not quantised"
		[ "$(grep -ao '"targets":\[' "$T/$d/model.glb" | wc -l)" -eq 2 ] ||
			fail "$d: not the bark's and the leaves' targets"
	done
	grep -q '"wind":{"strength":0.35,"angle":0,"seed":1,"height":' "$T/w/skeleton.json" ||
		fail "skeleton.json: no breeze"
	grep -q '"wind":{"strength":0.8,' "$T/w8/skeleton.json" || fail "skeleton.json: not --wind 0.8"
	"$GLTF_VALIDATE" "$T/w/model.glb" "$T/w8/model.glb" >"$T/validate.log" ||
		{ cat "$T/validate.log"; fail "glTF validator"; }
	grep -c ': 0 errors, 0 warnings,' "$T/validate.log" | grep -qx 2 ||
		{ cat "$T/validate.log"; fail "validator warnings"; }
	# a sketch is exported as a tree, swaying; an empty drawing has nothing to sway
	run --out "$T/flat" --replay "$DEMO"
	grep -aq '"animations":\[{"name":"wind",' "$T/flat/model.glb" || fail "the sketch does not sway"
	run --out "$T/empty"
	grep -aq '"animations"' "$T/empty/model.glb" && fail "an empty drawing with an animation"
	grep -q '"wind"' "$T/empty/skeleton.json" && fail "an empty drawing with a wind"
	usage_says 'bad --wind "1.5" (expected a strength from 0, still, to 1)' --headless --out "$T/x" \
		--wind 1.5
	usage_says 'bad --wind "-0.1" (expected a strength from 0, still, to 1)' --wind -0.1
	usage_says 'bad --wind "nan" (expected a strength from 0, still, to 1)' --wind nan
	usage_says 'bad --wind "" (expected a strength from 0, still, to 1)' --wind=
	usage_says "--wind does not go with --leaf (only --out, --opening and --size do)" --headless \
		--out "$T/x" --leaf maple --wind 0.5
	usage_says "--wind does not go with --support (only --out, --vine, --plant and --size do)" \
		--headless --out "$T/x" --support s.obj --vine default --plant 0,0,0 --wind 0.5
	[ ! -e "$T/x" ] || fail "a usage error wrote files"
	echo "model.glb sways at the breeze or --wind; model.obj and the drawing do not change"
}

t_malformed() {
	local dir=$SRC/malformed n=0 file line opt rc
	while read -r file line; do
		[ -n "$file" ] || continue
		case $file in *.edaha) opt=--load ;; *) opt=--replay ;; esac
		edaha --headless --out "$T/m" "$opt" "$dir/$file" >/dev/null 2>"$T/err"; rc=$?
		[ $rc -eq 2 ] || { cat "$T/err"; fail "$file: exit $rc, wanted 2"; }
		if [ "$line" -gt 0 ]; then want="$dir/$file:$line: "; else want="$dir/$file: "; fi
		grep -qF "edaha: $want" "$T/err" || { cat "$T/err"; fail "$file: message does not start with $want"; }
		[ ! -e "$T/m" ] || fail "$file: output written despite the error"
		n=$((n + 1))
	done < <(cat "$dir/EXPECT" "$dir/EXPECT-doc")
	[ $n -ge 20 ] || fail "only $n malformed inputs (want at least 20)"
	echo "$n malformed inputs rejected with exit 2 and file:line"
}

"t_$1"
