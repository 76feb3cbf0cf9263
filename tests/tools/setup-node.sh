#!/bin/sh
# SPDX-License-Identifier: MIT
# Installs the pinned node tools the tests use (the Khronos glTF validator) into
# tests/tools/node_modules from package.json + package-lock.json.
set -eu
top=$(CDPATH= cd -- "$(dirname -- "$0")/../.." && pwd)
exec "$top/tools/npm-pinned.sh" setup-node.sh "$top/tests/tools" gltf-validator
