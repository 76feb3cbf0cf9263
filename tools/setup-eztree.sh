#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs ez-tree 1.1.0 and three.js 0.167.1 (pinned by bench/eztree/package-lock.json) into
# bench/eztree/node_modules, which git ignores, for bench_generate's comparison with ez-tree
# (bench/eztree/bench.mjs). Nothing of theirs is committed.
set -eu
top=$(CDPATH= cd -- "$(dirname -- "$0")/.." && pwd)
exec "$top/tools/npm-pinned.sh" setup-eztree.sh "$top/bench/eztree" @dgreenheck/ez-tree
