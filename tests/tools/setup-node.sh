#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs the pinned node tools the tests use (the Khronos glTF validator) into
# tests/tools/node_modules from package.json + package-lock.json. Idempotent: a copy of
# the lock file in node_modules records what was installed, so a second run is instant.
set -eu

dir=$(CDPATH= cd -- "$(dirname -- "$0")" && pwd)
stamp="$dir/node_modules/.edaha-installed-lock.json"

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
	echo "setup-node.sh: node and npm are needed (Debian: apt-get install nodejs npm)" >&2
	exit 1
fi

if [ -f "$stamp" ] && cmp -s "$dir/package-lock.json" "$stamp" &&
	[ -f "$dir/node_modules/gltf-validator/package.json" ]; then
	echo "setup-node.sh: node tools already installed in $dir/node_modules"
	exit 0
fi

cd "$dir"
npm ci --no-audit --no-fund
cp package-lock.json "$stamp"
echo "setup-node.sh: installed node tools in $dir/node_modules"
