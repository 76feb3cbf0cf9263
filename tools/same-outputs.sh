#!/bin/bash
# Whether a change that should not change behaviour (a move, a rename, a split) writes the
# same files: builds commit BASE and the working tree (each in a temp dir, the same meson
# options), runs both on the same inputs and compares every file they write, byte for byte.
#   tools/same-outputs.sh BASE
# The runs: the headless demo, every tree preset (--generate), each leaf preset (--leaf), a
# vine on a pole (--support), the demo grown twice (--press grow, its voxels dumped) and the
# edit traces replayed. Prints one line a run ("same" or the files that differ) and exits 1
# if any differs. The inputs are the working tree's, for both.
set -euo pipefail
[ $# = 1 ] || { echo "usage: tools/same-outputs.sh BASE" >&2; exit 2; }
REPO=$(cd "$(dirname "$0")/.." && pwd)
base=$(git -C "$REPO" rev-parse --verify "$1^{commit}")
T=$(mktemp -d /tmp/edaha-same.XXXXXX)
trap 'git -C "$REPO" worktree remove --force "$T/base-src" 2>/dev/null || true; rm -rf "$T"' EXIT

build() { # source dir, build dir
	meson setup "$2" "$1" -Dtests=false >"$T/setup.log" 2>&1 ||
		{ tail -20 "$T/setup.log" >&2; exit 1; }
	meson compile -C "$2" edaha >"$T/compile.log" 2>&1 ||
		{ tail -20 "$T/compile.log" >&2; exit 1; }
}
git -C "$REPO" worktree add --detach -q "$T/base-src" "$base"
build "$T/base-src" "$T/base"
build "$REPO" "$T/head"

python3 "$REPO/tests/vine/support.py" pole "$T/pole.obj"
runs=(
	"demo|"
	"leaf-entire|--leaf entire"
	"leaf-hop|--leaf hop"
	"leaf-maple|--leaf maple --opening 0.5"
	"vine|--support $T/pole.obj --vine morning-glory --plant 0.025,0,0"
	"grown|--replay $REPO/tests/data/demo.edaha-trace --press 3d --press grow --press grow --dump-voxels"
)
for p in "$REPO"/presets/*.yaml; do
	runs+=("preset-$(basename "$p" .yaml)|--generate $p")
done
for t in "$REPO"/tests/data/edit-*.edaha-trace; do
	runs+=("$(basename "$t" .edaha-trace)|--replay $t")
done

differ=0
for r in "${runs[@]}"; do
	name=${r%%|*} args=${r#*|}
	for side in base head; do
		# shellcheck disable=SC2086 # args are words
		"$T/$side/platform/edaha" --headless $args --out "$T/out-$side/$name" \
			>"$T/$side-$name.log" 2>&1 || { echo "$name: $side exited $?"; cat "$T/$side-$name.log"; differ=1; continue 2; }
	done
	d=$(cd "$T/out-base/$name" && find . -type f | sort | while read -r f; do
		cmp -s "$f" "$T/out-head/$name/$f" || echo "${f#./}"
	done)
	extra=$(diff <(cd "$T/out-base/$name" && find . -type f | sort) \
		<(cd "$T/out-head/$name" && find . -type f | sort) || true)
	if [ -z "$d" ] && [ -z "$extra" ]; then
		echo "$name: same ($(find "$T/out-head/$name" -type f | wc -l) files)"
	else
		echo "$name: DIFFERS: $d ${extra:+(file lists differ)}"
		differ=1
	fi
done
exit $differ
