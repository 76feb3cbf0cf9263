#!/bin/sh
# SPDX-License-Identifier: MIT
# npm-pinned.sh NAME DIR PACKAGE: installs what DIR's package-lock.json pins into
# DIR/node_modules (which git ignores), without running any package's install scripts, once:
# a copy of the lock file in node_modules records what was installed, so a second run is
# instant while PACKAGE is there. NAME is the caller's, for messages.
set -eu

name=$1 dir=$2 package=$3
stamp="$dir/node_modules/.edaha-installed-lock.json"

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
	echo "$name: node and npm are needed (Debian: apt-get install nodejs npm)" >&2
	exit 1
fi

if [ -f "$stamp" ] && cmp -s "$dir/package-lock.json" "$stamp" &&
	[ -f "$dir/node_modules/$package/package.json" ]; then
	echo "$name: $package already installed in $dir/node_modules"
	exit 0
fi

cd "$dir"
npm ci --no-audit --no-fund --ignore-scripts
cp package-lock.json "$stamp"
echo "$name: installed $package in $dir/node_modules"
