#!/bin/bash
# SPDX-License-Identifier: MIT
# vines.sh: a drawing with a vine planted on its tree, exported by the edaha binary end to
# end (output.c, as the kiosk's export_set.c: the tree's exporters). Paths come from
# meson's environment: EDAHA, GLTF_VALIDATE, DEMO (a trace whose first branch is a trunk
# from the ground), EDAHA_GL_PRELOAD (ASan builds). The demo's drawing gets a vine op
# (docs/vines.md: `vine T X Y Z {parameters}`) planted beside the trunk's root; loaded, its
# skeleton.json is version 2 with the vine twined round the trunk, model.obj has the vine's
# objects, model.glb passes the Khronos validator without errors or warnings, and the
# drawing it writes back gives the same files.
set -uo pipefail
: "${EDAHA:?}" "${GLTF_VALIDATE:?}" "${DEMO:?}"
T=$(mktemp -d "${TMPDIR:-/tmp}/edaha-vines.XXXXXX")
trap 'rm -rf "$T"' EXIT

# fail, and edaha (the GL driver preloaded under ASan)
. "$(dirname "$0")/../tools/edaha.sh"
run() {
	edaha --headless "$@" >"$T/log" 2>&1 || { cat "$T/log" >&2; fail "edaha $* exited $?"; }
}

VINE='{edaha-vine: 1, internode: 0.06, radius: 0.002, step_time: 10, angle: 18, free_nodes: 1, twining: left, leaves_per_node: 1, cotyledons: 2, leaf_size: 0.012, points_per_internode: 8, ring_sides: 8, sweep: 2.25, internodes: 40, seed: 1}'

run --out "$T/tree" --replay "$DEMO"
# beside the trunk's root: its radius, the vine's and 5 mm out along +x
plant=$(python3 -c '
import json, sys
b = json.load(open(sys.argv[1]))["branches"][0]
x, y, z = b["points"][0]
print("%.6f %.6f %.6f" % (x + b["radii"][0] + 0.007, y, z))' "$T/tree/skeleton.json") ||
	fail "no trunk in the demo's skeleton.json"
# one more op in effect, after the strokes, before the tree's summary
awk -v vine="vine 99000000 $plant $VINE" '
	/^history / { $2++; $3++ }
	/^tree / { print vine }
	{ print }' "$T/tree/drawing.edaha" >"$T/vine.edaha" || fail "awk"
run --out "$T/vine" --load "$T/vine.edaha"

python3 - "$T/vine/skeleton.json" "$T/tree/skeleton.json" <<'PY' || fail "skeleton.json"
import json, math, sys
vine, tree = (json.load(open(p)) for p in sys.argv[1:])
assert vine["version"] == 2 and tree["version"] == 2, "version"
assert "vines" not in tree, "vines on a tree without them"
assert vine["branches"] == tree["branches"] and vine["leaves"] == tree["leaves"], "the tree changed"
assert len(vine["vines"]) == 1, "not one vine"
v = vine["vines"][0]
main = v["shoots"][0]
assert main["parent"] == -1 and len(main["axis"]) > 100, "the main shoot"
# twined round the trunk: many points touch it, each at the trunk's radius (and the
# vine's, and the bark's facets) from its axis
trunk = tree["branches"][0]
def from_axis(p):
    best = math.inf
    for a, b, ra, rb in zip(trunk["points"], trunk["points"][1:], trunk["radii"], trunk["radii"][1:]):
        ab = [q - o for q, o in zip(b, a)]
        ap = [q - o for q, o in zip(p, a)]
        t = max(0, min(1, sum(x * y for x, y in zip(ab, ap)) / max(sum(x * x for x in ab), 1e-12)))
        d = math.dist(p, [o + t * x for o, x in zip(a, ab)]) - (ra + t * (rb - ra))
        best = min(best, abs(d))
    return best
assert len(main["contacts"]) > 20, f'{len(main["contacts"])} contacts'
far = max(from_axis(main["axis"][i]) for i in main["contacts"])
assert far < 0.02, f"a contact {far} m off the bark"
assert len(v["leaves"]) > 10, "leaves"
print(f'vine: {len(v["shoots"])} shoots, {len(main["contacts"])} contacts (at most {far:.4f} m off the bark), {len(v["leaves"])} leaves')
PY

for o in "o bark" "o leaves" "o vine" "o vine-leaves"; do
	grep -qx "$o" "$T/vine/model.obj" || fail "model.obj has no \"$o\""
done
grep -qx "newmtl vine" "$T/vine/model.mtl" || fail "model.mtl has no vine material"
grep -q "^o vine" "$T/tree/model.obj" && fail "a tree without vines has vine objects"

"$GLTF_VALIDATE" "$T/vine/model.glb" >"$T/validator.log" 2>&1
rc=$?
cat "$T/validator.log"
[ $rc -eq 0 ] || fail "glTF validator"
grep -q "model.glb: 0 errors, 0 warnings," "$T/validator.log" || fail "the validator has warnings"

# what it wrote loads back to the same files
grep -q "^vine 99000000 " "$T/vine/drawing.edaha" || fail "drawing.edaha lost the vine"
run --out "$T/again" --load "$T/vine/drawing.edaha"
for f in skeleton.json model.glb model.obj model.mtl drawing.edaha; do
	cmp -s "$T/vine/$f" "$T/again/$f" || fail "$f differs when its drawing is loaded again"
done
echo "vines.sh: ok"
