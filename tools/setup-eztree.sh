#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs ez-tree 1.1.0 and three.js 0.167.1 (pinned by bench/eztree/package-lock.json) into
# bench/eztree/node_modules, which git ignores, for bench_generate's comparison with ez-tree
# (bench/eztree/bench.mjs). Nothing of theirs is committed. Idempotent: a copy of the lock
# file in node_modules records what was installed, so a second run is instant.
set -eu

dir=$(CDPATH= cd -- "$(dirname -- "$0")/../bench/eztree" && pwd)
stamp="$dir/node_modules/.edaha-installed-lock.json"

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
	echo "setup-eztree.sh: node and npm are needed (Debian: apt-get install nodejs npm)" >&2
	exit 1
fi

if [ -f "$stamp" ] && cmp -s "$dir/package-lock.json" "$stamp" &&
	[ -f "$dir/node_modules/@dgreenheck/ez-tree/package.json" ]; then
	echo "setup-eztree.sh: ez-tree already installed in $dir/node_modules"
	exit 0
fi

cd "$dir"
# neither package has install scripts; none may run
npm ci --no-audit --no-fund --ignore-scripts
cp package-lock.json "$stamp"
echo "setup-eztree.sh: installed ez-tree in $dir/node_modules; run build-dev/bench/bench_generate"
