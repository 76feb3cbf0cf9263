#!/bin/bash
# SPDX-License-Identifier: MIT
# The rules of functional trees (docs/functional-trees.md, docs/tree-params.md) asserted on
# what the real binary writes: gen.sh TEST. Paths come from meson's environment: EDAHA,
# GEN_CHECK (gen_check.c: the geometry), GLTF_VALIDATE, SRC (the source tree).
set -uo pipefail
: "${EDAHA:?}" "${GEN_CHECK:?}" "${SRC:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-gen.XXXXXX")
trap 'rm -rf "$T"' EXIT
HERE=$SRC/tests/gen
PRESETS="cherry zelkova hedge ball cone palm"

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
# run OUT ARGS...: a headless run that must succeed. The screen is small: these tests read
# the model and skeleton, which --size never changes (functional-trees.md, Precision).
run() {
	local out=$1 rc=0
	shift
	edaha --headless --size 160x100 --out "$out" "$@" >"$T/stdout" 2>"$T/stderr" || rc=$?
	[ $rc -eq 0 ] || { cat "$T/stderr" >&2; fail "edaha $* exited $rc"; }
}
gen() { # FILE OUT ARGS...
	local file=$1 out=$2
	shift 2
	run "$out" --generate "$file" "$@"
}
check() { "$GEN_CHECK" "$@" || fail "gen_check $*"; }
# param FILE KEY DEFAULT: a parameter file's value (gen_check param: libyaml), DEFAULT when
# the file leaves it out: the tests read the presets rather than copy their numbers
param() { "$GEN_CHECK" param "$@" || fail "gen_check param $*"; }
# lsystem NAME KEY: VALUE...: a parameter file $T/NAME.yaml with those lines after the head
lsystem() {
	local name=$1
	shift
	{ echo "edaha-tree: 1"; echo "type: lsystem"; printf '%s\n' "$@"; } >"$T/$name.yaml"
}

# 1. Branch counts, children at their parent's tip, lengths by the ratios, levels; 2 and 3
# children, levels 2..8, a vertical and a leaning trunk.
t_structure() {
	local l
	for l in 2 3 4 5 6 7 8; do
		lsystem "two$l" "levels: $l" "children: 2" "ratios: [0.8, 0.6]" "leaves: {amount: 2}"
		gen "$T/two$l.yaml" "$T/two$l"
		check tree "$T/two$l/skeleton.json" "$l" 2 0.8,0.6 2
		lsystem "three$l" "levels: $l" "children: 3" "ratios: [0.9, 0.75, 0.6]" \
			"trunk: {start: [0.3, 0, -0.2], end: [1, 2, 0.5]}" "angle: {min: 10, max: 80, randomness: 1}" \
			"leaves: {amount: 1}"
		gen "$T/three$l.yaml" "$T/three$l"
		check tree "$T/three$l/skeleton.json" "$l" 3 0.9,0.75,0.6 1
	done
	# the checks can fail: ratios 0.1% off, a level more
	"$GEN_CHECK" tree "$T/two8/skeleton.json" 8 2 0.8008,0.6 2 >/dev/null 2>&1 && fail "gen_check tree passed a wrong ratio"
	"$GEN_CHECK" tree "$T/three7/skeleton.json" 8 3 0.9,0.75,0.6 1 >/dev/null 2>&1 && fail "gen_check tree passed a wrong level count"
	return 0
}

# 2. MakeTree's angle: within [min, max] whatever the seed, spread over all of it at
# randomness 1, over the middle randomness x (max - min) at less, and the same tree for
# every seed at 0.
t_angles() {
	local seed files
	lsystem full "levels: 7" "angle: {min: 20, max: 60, randomness: 1}" "leaves: {amount: 0}"
	files=()
	for seed in 1 2 3 4 5 6 7 8; do
		gen "$T/full.yaml" "$T/full$seed" --seed $seed
		files+=("$T/full$seed/skeleton.json")
	done
	# 8 x 126 angles: the widest gap a uniform draw leaves at an end is far below 3%
	check angles 20 60 1 0.03 "${files[@]}"
	cmp -s "$T/full1/skeleton.json" "$T/full2/skeleton.json" && fail "seeds 1 and 2 gave the same tree"
	# three children, a wide range from 0
	lsystem three "levels: 5" "children: 3" "angle: {min: 0, max: 110, randomness: 1}" "leaves: {amount: 0}"
	files=()
	for seed in 11 12 13 14; do
		gen "$T/three.yaml" "$T/three$seed" --seed $seed
		files+=("$T/three$seed/skeleton.json")
	done
	check angles 0 110 1 0.03 "${files[@]}"
	# randomness 0.4: mid +- 0.2 (max - min), and all of that
	lsystem part "levels: 7" "angle: {min: 10, max: 90, randomness: 0.4}" "leaves: {amount: 0}"
	files=()
	for seed in 1 2 3 4; do
		gen "$T/part.yaml" "$T/part$seed" --seed $seed
		files+=("$T/part$seed/skeleton.json")
	done
	check angles 10 90 0.4 0.03 "${files[@]}"
	# randomness 0: every angle the middle, every seed the same tree (skeleton.json's last
	# key, "wind", holds the seed its phases come from: left out)
	lsystem none "levels: 6" "angle: {min: 15, max: 75, randomness: 0}" "leaves: {amount: 2}"
	for seed in 1 2 77 18446744073709551615; do
		gen "$T/none.yaml" "$T/none$seed" --seed $seed
		cmp -s <(sed 's/,"wind":{.*$/}/' "$T/none1/skeleton.json") \
			<(sed 's/,"wind":{.*$/}/' "$T/none$seed/skeleton.json") ||
			fail "randomness 0: seeds 1 and $seed gave different trees"
	done
	check angles 15 75 0 0 "$T/none1/skeleton.json"
	# the checks can fail: a range 1 degree narrower at either end
	"$GEN_CHECK" angles 21 60 1 0.03 "$T/full1/skeleton.json" >/dev/null 2>&1 && fail "gen_check angles passed a narrower range"
	"$GEN_CHECK" angles 20 59 1 0.03 "$T/full1/skeleton.json" >/dev/null 2>&1 && fail "gen_check angles passed a narrower range"
	return 0
}

# 3. Siblings spread apart about their parent's axis; the paper's alpha at a vertical
# trunk's foot.
t_spread() {
	local spread children
	for spread in 0 30 90 140 150 180 250 360; do
		lsystem "s$spread" "levels: 3" "spread: $spread" "angle: {min: 20, max: 50, randomness: 1}" \
			"leaves: {amount: 0}"
		gen "$T/s$spread.yaml" "$T/s$spread" --seed $((spread + 5))
		check spread "$spread" "$T/s$spread/skeleton.json"
	done
	for spread in 120 75; do
		children=3
		lsystem "t$spread" "levels: 3" "children: $children" "spread: $spread" "twist: 35" \
			"angle: {min: 30, max: 60, randomness: 1}" "leaves: {amount: 0}"
		gen "$T/t$spread.yaml" "$T/t$spread"
		check spread "$spread" "$T/t$spread/skeleton.json"
	done
	# the check can fail: 1.5 degrees off
	"$GEN_CHECK" spread 121.5 "$T/t120/skeleton.json" >/dev/null 2>&1 && fail "gen_check spread passed 121.5 for 120"
	return 0
}

# 4. Thickness: the trunk's base, every tip thickness_ratio of its base, children from
# their parent's tip, linear along each branch; for every type.
t_radii() {
	lsystem two "levels: 6" "thickness: 0.3" "thickness_ratio: 0.6" "leaves: {amount: 0}"
	gen "$T/two.yaml" "$T/two"
	check radii lsystem 0.3 0.6 "$T/two/skeleton.json"
	lsystem three "levels: 5" "children: 3" "thickness: 0.05" "thickness_ratio: 0.9"
	gen "$T/three.yaml" "$T/three"
	check radii lsystem 0.05 0.9 "$T/three/skeleton.json"
	local p type
	for p in $PRESETS; do
		gen "$SRC/presets/$p.yaml" "$T/$p"
		type=$(param "$SRC/presets/$p.yaml" type lsystem)
		case $type in
		lsystem) check radii lsystem "$(param "$SRC/presets/$p.yaml" thickness 0.15)" \
			"$(param "$SRC/presets/$p.yaml" thickness_ratio 0.7)" "$T/$p/skeleton.json" ;;
		shrub) check radii shrub "$(param "$SRC/presets/$p.yaml" thickness 0.06)" \
			"$(param "$SRC/presets/$p.yaml" thickness_ratio 0.75)" "$T/$p/skeleton.json" ;;
		palm) check radii palm "$(param "$SRC/presets/$p.yaml" thickness 0.2)" \
			"$(param "$SRC/presets/$p.yaml" thickness_ratio 0.7)" "$T/$p/skeleton.json" ;;
		esac
	done
	# a wrong thickness must fail: the check can
	"$GEN_CHECK" radii lsystem 0.01 0.7 "$T/cherry/skeleton.json" >/dev/null 2>&1 &&
		fail "gen_check radii passed a wrong thickness"
	return 0
}

# 5. leaves.amount on each tip, none elsewhere; 0 is bare.
t_leaves() {
	local amount
	for amount in 0 1 7; do
		lsystem "a$amount" "levels: 6" "leaves: {amount: $amount}"
		gen "$T/a$amount.yaml" "$T/a$amount"
		check tree "$T/a$amount/skeleton.json" 6 2 0.75,0.7 $amount
	done
	lsystem most "levels: 3" "children: 3" "leaves: {amount: 200, size: 0.05}"
	gen "$T/most.yaml" "$T/most"
	check tree "$T/most/skeleton.json" 3 3 0.75,0.7,0.65 200
	grep -q '"leaves":\[\]' "$T/a0/skeleton.json" || fail "amount 0: leaves in skeleton.json"
	# the check can fail
	"$GEN_CHECK" tree "$T/a7/skeleton.json" 6 2 0.75,0.7 6 >/dev/null 2>&1 && fail "gen_check tree passed 6 leaves a tip for 7"
	return 0
}

# 6. precision: bark triangles about linear in it, the skeleton the same.
t_precision() {
	local n args=()
	for n in 4 8 12 16; do
		lsystem "p$n" "precision: $n" "levels: 6" "children: 3" "leaves: {amount: 2}"
		gen "$T/p$n.yaml" "$T/p$n"
		cmp -s "$T/p4/skeleton.json" "$T/p$n/skeleton.json" ||
			fail "precision $n changed skeleton.json"
		args+=("$n" "$T/p$n/model.glb")
	done
	check precision "${args[@]}"
	# the check can fail: not linear when one run's sides are misnamed
	"$GEN_CHECK" precision 4 "$T/p4/model.glb" 8 "$T/p8/model.glb" 10 "$T/p12/model.glb" 16 "$T/p16/model.glb" \
		>/dev/null 2>&1 && fail "gen_check precision passed a run of 12 sides as 10"
	cmp -s "$T/p4/model.glb" "$T/p16/model.glb" && fail "precision changed nothing in model.glb"
	# the view never changes the drawing's n: a large screen exports what a small one does
	edaha --headless --size 1280x800 --out "$T/large" --generate "$T/p8.yaml" >/dev/null ||
		fail "--size 1280x800 failed"
	cmp -s "$T/p8/model.glb" "$T/large/model.glb" || fail "--size changed model.glb"
	cmp -s "$T/p8/model.obj" "$T/large/model.obj" || fail "--size changed model.obj"
	return 0
}

# The shrubs: the shape presets, and shrubs of our own grown to fill their shapes.
SHRUBS="presets/hedge.yaml presets/ball.yaml presets/cone.yaml tests/gen/trees/shrub-sphere.yaml
tests/gen/trees/shrub-box.yaml tests/gen/trees/shrub-cone.yaml tests/gen/trees/shrub-default.yaml"

# shape_of FILE: its clip shape as gen_check clip takes it, with tree-params.md's defaults
shape_of() {
	local f=$1 centre
	centre=$(param "$f" clip.center "0 1.5 0")
	case $(param "$f" clip.shape sphere) in
	sphere) echo "sphere $centre $(param "$f" clip.radius 1)" ;;
	box) echo "box $centre $(param "$f" clip.size "2 1 1")" ;;
	cone) echo "cone $centre $(param "$f" clip.radius 1) $(param "$f" clip.height 2)" ;;
	esac
}

# fill_delta FILE: a surface point is leafy with a leaf's centre within two leaf lengths
fill_delta() { awk -v s="$(param "$1" leaves.size 0.15)" 'BEGIN { print 2 * s }'; }

# trunk_alone FILE OUT: the shrub's trunk without its crown: its mesh is the first part of
# the shrub's bark (check_clip.c). A shrub always grows a crown to its shape, so the trunk is
# grown alone as an L-system tree of one level with the same trunk, radii and sides.
trunk_alone() {
	local name start height
	name=$(basename "$1" .yaml)
	start=$(param "$1" trunk.start "0 0 0")
	height=$(param "$1" trunk_height 0.8)
	# shellcheck disable=SC2086
	set -- "$1" "$2" $start
	{
		echo "edaha-tree: 1"
		echo "type: lsystem"
		echo "precision: $(param "$1" precision 6)"
		echo "trunk: {start: [$3, $4, $5], end: [$3, $(awk -v y="$4" -v h="$height" 'BEGIN { printf "%.17g", y + h }'), $5]}"
		echo "levels: 1"
		echo "thickness: $(param "$1" thickness 0.06)"
		echo "thickness_ratio: $(param "$1" thickness_ratio 0.75)"
		echo "leaves: {amount: 0}"
	} >"$T/$name-trunk.yaml"
	gen "$T/$name-trunk.yaml" "$2"
}

# 7. A shrub's crown inside its shape, in skeleton.json and in model.glb; the shrubs of
# tests/gen/trees/ grown to fill it (check_clip.c: the measure). The presets' fill is
# t_shrub_fill_presets.
t_shrubs() {
	local file name fill
	for file in $SHRUBS; do
		name=$(basename "$file" .yaml)
		gen "$SRC/$file" "$T/$name"
		trunk_alone "$SRC/$file" "$T/$name-trunk"
		echo "== $file: $(shape_of "$SRC/$file")"
		fill=()
		case $file in tests/gen/trees/shrub-[sbc]*) fill=(fill "$(fill_delta "$SRC/$file")" 0.9) ;; esac
		# shellcheck disable=SC2046
		check clip "$T/$name/skeleton.json" $(shape_of "$SRC/$file") \
			glb "$T/$name/model.glb" "$T/$name-trunk/model.glb" "${fill[@]}"
	done
	# the check can fail: a ball 5 cm smaller than the one grown into
	# shellcheck disable=SC2046
	"$GEN_CHECK" clip "$T/ball/skeleton.json" $(shape_of "$SRC/presets/ball.yaml" | awk '{ $5 -= 0.05; print }') \
		>/dev/null 2>&1 && fail "gen_check clip passed a ball 5 cm too small"
	return 0
}

# The shape presets and a shrub of defaults fill their shapes by the measure t_shrubs' own
# shrubs meet (check_clip.c); prints each one's numbers (they fell short before the presets'
# ratios reached the surface).
t_shrub_fill_presets() {
	local file name status=0
	for file in presets/hedge.yaml presets/ball.yaml presets/cone.yaml tests/gen/trees/shrub-default.yaml; do
		name=$(basename "$file" .yaml)
		gen "$SRC/$file" "$T/$name"
		echo "== $file: $(shape_of "$SRC/$file")"
		# shellcheck disable=SC2046
		"$GEN_CHECK" clip "$T/$name/skeleton.json" $(shape_of "$SRC/$file") \
			fill "$(fill_delta "$SRC/$file")" 0.9 || status=1
	done
	[ $status -eq 0 ] || fail "shrubs that do not fill their shapes (above)"
}

# Issue 24: a shrub fills its shape whatever its parameters (the property itself, on random
# files: test_shrub_fill.c). Here end to end: the issue's file (a sparse crown whose trunk's
# top is near the bottom of its sphere), and the kiosk's buttons on the shape presets: the
# ball after fewer twice, narrower and shorter, the hedge after fewer twice. Each is inside
# its shape and fills it by the measure of t_shrubs, with the parameters its drawing ends
# with (a press that changes nothing is refused: fewer stops where the shape decides).
t_shrub_kiosk() {
	local name file status=0
	gen "$HERE/trees/shrub-issue24.yaml" "$T/issue24"
	run "$T/ball" --press tpl-ball --press gen-fewer --press gen-fewer --press gen-narrower --press gen-shorter
	run "$T/hedge" --press tpl-hedge --press gen-fewer --press gen-fewer
	for name in issue24 ball hedge; do
		# the last generate op's parameters: one line of YAML (tree-params.md, In a drawing)
		grep '^generate ' "$T/$name/drawing.edaha" | tail -1 | cut -d' ' -f5- >"$T/$name.yaml"
		file=$T/$name.yaml
		echo "== $name: $(grep -c '^generate ' "$T/$name/drawing.edaha") generate ops, levels $(param "$file" levels 7), $(shape_of "$file")"
		# shellcheck disable=SC2046
		"$GEN_CHECK" clip "$T/$name/skeleton.json" $(shape_of "$file") fill "$(fill_delta "$file")" 0.9 ||
			status=1
	done
	[ $status -eq 0 ] || fail "shrubs that do not fill their shapes (above)"
}

# 8. A palm: every frond at the trunk's top, the trunk bare; fronds evenly round an upright
# trunk.
t_palm() {
	gen "$SRC/presets/palm.yaml" "$T/palm"
	check palm "$(param "$SRC/presets/palm.yaml" fronds 12)" "$(param "$SRC/presets/palm.yaml" leaves.amount 40)" \
		"$T/palm/skeleton.json"
	gen "$HERE/trees/palm-upright.yaml" "$T/upright"
	check palm 9 11 "$T/upright/skeleton.json" even
	check radii palm 0.2 0.7 "$T/upright/skeleton.json"
	gen "$HERE/trees/palm-leaning.yaml" "$T/leaning"
	check palm 64 0 "$T/leaning/skeleton.json"
	# the check can fail
	"$GEN_CHECK" palm 9 12 "$T/upright/skeleton.json" >/dev/null 2>&1 && fail "gen_check palm passed 12 leaflets for 11"
	return 0
}

# without_season FILE: skeleton.json but its "season"
without_season() { sed 's/"season":"[a-z]*",//' "$1"; }
season_of() { grep -o '"season":"[a-z]*"' "$1" | cut -d'"' -f4; }

# 9. The season button cycles spring -> summer -> autumn -> winter and changes no branch
# and no leaf: only skeleton.json's "season".
t_seasons() {
	local entry f n presses want press i
	# a full round on the cherry (spring) and the palm (summer); two presses on the others
	for entry in presets/cherry.yaml:4 presets/palm.yaml:4 presets/ball.yaml:2 tests/gen/trees/lsystem-leaning.yaml:2; do
		f=${entry%:*} presses=${entry#*:}
		n=$(basename "$f" .yaml)
		gen "$SRC/$f" "$T/$n-0"
		want=$(param "$SRC/$f" season summer)
		[ "$(season_of "$T/$n-0/skeleton.json")" = "$want" ] ||
			fail "$f: starts in $(season_of "$T/$n-0/skeleton.json"), wanted $want"
		press=()
		for i in $(seq "$presses"); do
			press+=(--press season)
			gen "$SRC/$f" "$T/$n-$i" "${press[@]}"
			cmp -s <(without_season "$T/$n-0/skeleton.json") <(without_season "$T/$n-$i/skeleton.json") ||
				fail "$f: $i presses of season changed the branches or leaves"
			case $(season_of "$T/$n-$((i - 1))/skeleton.json")/$(season_of "$T/$n-$i/skeleton.json") in
			spring/summer | summer/autumn | autumn/winter | winter/spring) ;;
			*) fail "$f: press $i went from $(season_of "$T/$n-$((i - 1))/skeleton.json") to $(season_of "$T/$n-$i/skeleton.json")" ;;
			esac
			grep -q "^season [0-9]* $(season_of "$T/$n-$i/skeleton.json")\$" "$T/$n-$i/drawing.edaha" ||
				fail "$f: the drawing has no season op for $(season_of "$T/$n-$i/skeleton.json")"
		done
		if [ "$presses" -eq 4 ]; then
			cmp -s "$T/$n-0/skeleton.json" "$T/$n-4/skeleton.json" || fail "$f: four presses are not a full round"
		fi
		echo "$f: $want and $presses presses on; branches and leaves unchanged"
	done
}

# 10. A drawing stores the parameters, not the tree: --load of what --generate wrote gives
# the same model and skeleton, and cherry's drawing is under 1% of its model. A template
# pressed gives the tree of its preset file.
t_round_trip() {
	local p glb drawing
	for p in $PRESETS; do
		gen "$SRC/presets/$p.yaml" "$T/$p-a"
		run "$T/$p-b" --load "$T/$p-a/drawing.edaha"
		cmp -s "$T/$p-a/model.glb" "$T/$p-b/model.glb" || fail "$p: --load gave another model.glb"
		cmp -s "$T/$p-a/skeleton.json" "$T/$p-b/skeleton.json" || fail "$p: --load gave another skeleton.json"
		cmp -s "$T/$p-a/drawing.edaha" "$T/$p-b/drawing.edaha" || fail "$p: --load saved another drawing"
		grep -q '^generate ' "$T/$p-a/drawing.edaha" || fail "$p: no generate op in the drawing"
		run "$T/$p-tpl" --press "tpl-$p"
		cmp -s "$T/$p-a/skeleton.json" "$T/$p-tpl/skeleton.json" ||
			fail "--press tpl-$p and --generate presets/$p.yaml gave different trees"
		echo "$p: --generate, --load and --press tpl-$p give the same tree"
	done
	glb=$(stat -c %s "$T/cherry-a/model.glb")
	drawing=$(stat -c %s "$T/cherry-a/drawing.edaha")
	echo "cherry: drawing.edaha $drawing bytes, model.glb $glb bytes ($(awk -v d="$drawing" -v g="$glb" 'BEGIN { printf "%.3f", 100 * d / g }')%)"
	[ $((drawing * 100)) -lt "$glb" ] || fail "cherry's drawing is not under 1% of its model.glb"
	# and the same for a file of every key, another seed
	gen "$HERE/trees/lsystem-leaning.yaml" "$T/own-a" --seed 1234
	run "$T/own-b" --load "$T/own-a/drawing.edaha"
	cmp -s "$T/own-a/model.glb" "$T/own-b/model.glb" || fail "lsystem-leaning: --load gave another model.glb"
	cmp -s "$T/own-a/skeleton.json" "$T/own-b/skeleton.json" || fail "lsystem-leaning: --load gave another skeleton.json"
}

# 11. Every generated model.glb passes the Khronos validator.
t_validator() {
	local p f i rc press files=()
	for p in $PRESETS; do
		gen "$SRC/presets/$p.yaml" "$T/$p"
		files+=("$T/$p/model.glb")
	done
	for f in "$HERE"/trees/*.yaml; do
		p=$(basename "$f" .yaml)
		gen "$f" "$T/$p"
		files+=("$T/$p/model.glb")
	done
	# the cherry in its other seasons (its file's is spring): leaves of other colours, or none
	press=()
	for i in 1 2 3; do
		press+=(--press season)
		gen "$SRC/presets/cherry.yaml" "$T/season$i" "${press[@]}"
		files+=("$T/season$i/model.glb")
	done
	"$GLTF_VALIDATE" "${files[@]}" >"$T/validator.log"
	rc=$?
	grep -E 'errors|error:' "$T/validator.log"
	[ $rc -ne 77 ] || exit 77
	[ $rc -eq 0 ] || { cat "$T/validator.log"; fail "glTF validator"; }
	[ "$(grep -c ': 0 errors' "$T/validator.log")" -eq ${#files[@]} ] || fail "the validator did not report on every file"
}

# refused FILE LINE TEXT OPTION: edaha OPTION FILE exits 2 with one line, "edaha: FILE:LINE: "
# (LINE 0: "edaha: FILE: ") and TEXT after it, and writes nothing: --out is not made, or an
# empty one (every other time) stays empty
REFUSED=0
refused() {
	local file=$1 line=$2 text=$3 opt=$4 rc=0 want msg
	rm -rf "$T/out"
	REFUSED=$((REFUSED + 1))
	[ $((REFUSED % 2)) -eq 0 ] && mkdir "$T/out"
	edaha --headless --size 160x100 --out "$T/out" "$opt" "$file" >/dev/null 2>"$T/err" || rc=$?
	msg=$(cat "$T/err")
	[ $rc -eq 2 ] || { echo "$msg"; fail "$file: exit $rc, wanted 2"; }
	[ "$(wc -l <"$T/err")" -eq 1 ] || { echo "$msg"; fail "$file: not one line"; }
	if [ "$line" -gt 0 ]; then want="edaha: $file:$line: "; else want="edaha: $file: "; fi
	case $msg in
	"$want"*"$text"*) ;;
	*) echo "$msg"; fail "$file: wanted \"$want...$text...\"" ;;
	esac
	[ ! -e "$T/out" ] || [ -z "$(ls -A "$T/out")" ] || fail "$file: wrote $(ls "$T/out")"
}

# refuse_listed LIST: refused for each FILE LINE TEXT in LIST (tests/gen/malformed/EXPECT)
refuse_listed() {
	local dir=$HERE/malformed file line text opt n=0
	while read -r file line text; do
		case $file in '' | '#'*) continue ;; esac
		case $file in *.edaha) opt=--load ;; *) opt=--generate ;; esac
		[ -f "$dir/$file" ] || fail "$1 lists $file, which is not there"
		refused "$dir/$file" "$line" "$text" "$opt"
		n=$((n + 1))
	done <"$dir/$1"
	echo "$n files of $1 refused with exit 2 and FILE:LINE"
}

# 12. Malformed and hostile parameter files, in a file and in a drawing: exit 2, one line
# naming the file and the line at fault, nothing written.
t_malformed() {
	local f
	refuse_listed EXPECT
	# every file there is listed
	for f in "$HERE"/malformed/*.yaml "$HERE"/malformed/*.edaha; do
		grep -q "^$(basename "$f") " "$HERE/malformed/EXPECT" ||
			fail "$f is in no list"
	done
	# whole-file faults: too large for a parameter file (64 KiB, told at its first line), for
	# any input (1 MiB), missing, a directory, a device (no line)
	{ echo "edaha-tree: 1"; head -c 1000000 /dev/zero | tr '\0' '#'; echo; } >"$T/1mb.yaml"
	refused "$T/1mb.yaml" 1 "larger than 65536 bytes" --generate
	head -c 2000000 /dev/zero >"$T/2mb.yaml"
	refused "$T/2mb.yaml" 0 "file too large" --generate
	refused "$T/missing.yaml" 0 "No such file or directory" --generate
	refused "$HERE/malformed" 0 "Is a directory" --generate
	refused /dev/null 0 "not a regular file" --generate
	# a drawing's generate line longer than a parameter file may be names its line
	{
		printf 'edaha-drawing 5\nseed 1\nhistory 1 1\n'
		printf 'generate 100000 1 7 {edaha-tree: 1, levels: 4%70000s}\n' ''
		printf 'tree 0 0\nend\n'
	} >"$T/long-line.edaha"
	refused "$T/long-line.edaha" 4 "larger than 65536 bytes" --load
	# over what a good run wrote: nothing changes
	gen "$SRC/presets/palm.yaml" "$T/good"
	cp -r "$T/good" "$T/before"
	edaha --headless --out "$T/good" --generate "$HERE/malformed/levels-13.yaml" 2>/dev/null
	[ $? -eq 2 ] || fail "levels-13.yaml over a good run: not exit 2"
	diff -r "$T/before" "$T/good" >/dev/null || fail "levels-13.yaml over a good run changed its files"
}

# tree-params.md counts a shrub's leaves as leaves.amount "on each of them but the trunk",
# and so does gen_count_leaves (the limit check): a shrub of levels 1 has a bare trunk
# (fuzz_gen_read found it putting them there)
t_shrub_trunk_leaves() {
	local n
	printf 'edaha-tree: 1\ntype: shrub\nlevels: 1\nleaves: {amount: 4}\n' >"$T/one.yaml"
	gen "$T/one.yaml" "$T/one"
	n=$(grep -o '"branch":0,' "$T/one/skeleton.json" | wc -l)
	echo "a shrub of levels 1: $n leaves on its trunk"
	[ "$n" -eq 0 ] || fail "a shrub's trunk has $n leaves"
}

# 13. Generator versions (docs/functional-trees.md, "Generator versions"): a drawing saved
# before version 2 keeps its trees. versions/ holds what edaha at 4394a65 (generator
# version 1, the last before issue 24's shrubs) wrote for --generate of four presets: their
# drawings and the digests of their skeleton.json (SHA256SUMS: the trees, not the meshes,
# which later work may draw otherwise; test_gen_version.c checks 500 trees' digests).
# --load of each gives them byte for byte and saves the same drawing (its generate line
# keeps G = 1). A parameter button on the old ball makes an op of this
# edaha's version: the ball a template tap and the same press give now. The drawing with
# both ops loads to the same tree, and undo there brings the old ball back.
t_versions() {
	local p v=$HERE/versions
	for p in ball hedge cone cherry; do
		run "$T/$p" --load "$v/$p/drawing.edaha"
		cmp -s "$v/$p/drawing.edaha" "$T/$p/drawing.edaha" || fail "$p: --load saved another drawing"
	done
	# the trees: skeleton.json's last key, "wind" (issue 26), came after 4394a65
	for p in ball hedge cone cherry; do
		mkdir -p "$T/v1/$p"
		sed 's/,"wind":{.*$/}/' "$T/$p/skeleton.json" >"$T/v1/$p/skeleton.json"
	done
	(cd "$T/v1" && sha256sum --check --quiet "$v/SHA256SUMS") || fail "a version 1 drawing's tree changed (above)"
	echo "version 1 drawings (ball, hedge, cone, cherry): skeleton.json as edaha 4394a65 wrote it"
	run "$T/old-leafier" --load "$v/ball/drawing.edaha" --press gen-leafier
	run "$T/new-leafier" --press tpl-ball --press gen-leafier
	[ "$(grep '^generate ' "$T/old-leafier/drawing.edaha" | cut -d' ' -f3 | tr '\n' ' ')" = "1 2 " ] ||
		fail "leafier on a version 1 ball: not a version 2 op after the version 1 one"
	cmp -s "$T/old-leafier/skeleton.json" "$T/new-leafier/skeleton.json" ||
		fail "leafier on a version 1 ball did not give the ball of today's leafier"
	run "$T/both" --load "$T/old-leafier/drawing.edaha"
	cmp -s "$T/old-leafier/drawing.edaha" "$T/both/drawing.edaha" || fail "a drawing of versions 1 and 2 saved another"
	cmp -s "$T/old-leafier/skeleton.json" "$T/both/skeleton.json" || fail "a drawing of versions 1 and 2 loaded another tree"
	run "$T/undone" --load "$T/old-leafier/drawing.edaha" --press undo
	cmp -s "$T/ball/skeleton.json" "$T/undone/skeleton.json" || fail "undo of leafier did not give the version 1 ball"
	echo "leafier on the version 1 ball: a version 2 op, today's ball; undo: the version 1 ball"
}

"t_$1"
