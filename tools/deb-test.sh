#!/bin/bash
# Builds edaha's Debian package (debian/) for this machine's architecture from a copy of
# the checkout, checks it with lintian, and installs, upgrades, removes and purges it in
# a throw-away Debian 12 root (mmdebstrap) where tests/deb/in-root.sh checks each step.
# One line a check, "ok - NAME" or "not ok - NAME" (tools/test counts them); exit 1 if
# any failed. Nothing is written into the checkout.
#   tools/deb-test.sh [OUT]   OUT keeps the .deb, .changes and logs (default: a temp dir,
#                             deleted afterwards)
#   Environment: MIRROR (default http://deb.debian.org/debian); DEB_TEST_CACHE keeps the
#   throw-away root's downloaded packages (default /tmp/edaha-image-cache/apt-deb-test,
#   beside images/build.sh's)
# Packages: dpkg-dev debhelper lintian mmdebstrap fakeroot git (tools/deps.sh TEST_PKGS);
# mmdebstrap runs as root (or unprivileged with user namespaces and subuids).
set -euo pipefail
REPO=$(cd "$(dirname "$0")/.." && pwd)
T0=$(date +%s)
secs() { echo $(($(date +%s) - T0)); }
n_ok=0 n_fail=0
ok() { echo "ok - $*"; n_ok=$((n_ok + 1)); }
notok() { echo "not ok - $*"; n_fail=$((n_fail + 1)); }

WORK=$(mktemp -d /tmp/edaha-deb.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
if [ $# -ge 1 ]; then mkdir -p "$1"; OUT=$(realpath "$1"); else OUT=$WORK/out; mkdir "$OUT"; fi
chmod 755 "$WORK" # apt in the root downloads as _apt

# --- 1. build, from a copy: the tracked files as they are in the working tree ---------
mkdir "$WORK/src" "$WORK/build"
git -C "$REPO" ls-files -z | tar -C "$REPO" --null -T - -cf - | tar -C "$WORK/build" -xf -
mv "$WORK/build" "$WORK/src/edaha" # dpkg-buildpackage writes its files beside the tree
if (cd "$WORK/src/edaha" && dpkg-buildpackage -b -us -uc) >"$OUT/build.log" 2>&1; then
	ok "dpkg-buildpackage -b ($(secs) s)"
else
	notok "dpkg-buildpackage -b ($(secs) s)"; tail -30 "$OUT/build.log"
	echo "deb: $n_ok passed, $n_fail failed"; exit 1
fi
arch=$(dpkg --print-architecture)
version=$(dpkg-parsechangelog -l "$REPO/debian/changelog" -S Version)
deb=edaha_${version}_$arch.deb
cp "$WORK/src/$deb" "$WORK/src/edaha_${version}_$arch.changes" "$WORK/src"/*.buildinfo \
	"$WORK/src"/edaha-dbgsym_*.deb "$OUT/"
rm -rf "$WORK/src"

# --- 2. lintian: no error and no warning that debian/edaha.lintian-overrides does not
# explain; the rest (info, pedantic) is listed ---
t=$(date +%s)
# (--fail-on warning would count the overridden ones with --show-overrides: the tags
# shown are read instead; an error, even overridden, or lintian failing fails)
lrc=0
lintian --display-info --pedantic --show-overrides "$OUT/edaha_${version}_$arch.changes" >"$OUT/lintian.log" 2>&1 || lrc=$?
if [ "$lrc" = 0 ] && ! grep -qE '^[EW]: ' "$OUT/lintian.log"; then
	ok "lintian: 0 errors, 0 warnings ($(($(date +%s) - t)) s; $(grep -c '^[IP]: ' "$OUT/lintian.log" || true) info/pedantic tags, $(grep -c '^O: ' "$OUT/lintian.log" || true) overridden)"
else
	notok "lintian (exit $lrc)"
fi
grep -E '^[EWIPXO]: ' "$OUT/lintian.log" | sed 's/^/  lintian: /' || true

# --- 3. a throw-away Debian 12 root: install, check, upgrade, remove, purge -----------
CACHE=${DEB_TEST_CACHE:-/tmp/edaha-image-cache/apt-deb-test}
mkdir -p "$CACHE"
cp "$OUT/$deb" "$REPO/tests/deb/in-root.sh" "$WORK/"
MIRROR=${MIRROR:-http://deb.debian.org/debian}
t=$(date +%s)
rc=0
# shellcheck disable=SC2016 # the hooks' $1 is mmdebstrap's root
mmdebstrap --variant=apt --architectures="$arch" --aptopt='Acquire::Retries "3"' \
	--skip=essential/unlink \
	--setup-hook='mkdir -p "$1/var/cache/apt/archives"' \
	--setup-hook="sync-in $CACHE /var/cache/apt/archives/" \
	--customize-hook="copy-in $WORK/$deb $WORK/in-root.sh /tmp/" \
	--customize-hook="chroot \"\$1\" sh /tmp/in-root.sh /tmp/$deb $version" \
	--customize-hook="sync-out /var/cache/apt/archives $CACHE" \
	bookworm /dev/null "deb $MIRROR bookworm main" >"$OUT/root.log" 2>&1 || rc=$?
grep -E '^(not )?ok - ' "$OUT/root.log" | while IFS= read -r line; do echo "$line"; done
n_ok=$((n_ok + $(grep -c '^ok - ' "$OUT/root.log" || true)))
n_fail=$((n_fail + $(grep -c '^not ok - ' "$OUT/root.log" || true)))
if [ "$rc" = 0 ] && grep -q '^in-root: done' "$OUT/root.log"; then
	ok "throw-away bookworm root ($(($(date +%s) - t)) s)"
else
	notok "throw-away bookworm root (mmdebstrap exit $rc, $(($(date +%s) - t)) s)"
	grep -v '^I: ' "$OUT/root.log" | tail -40
fi

echo "deb: $n_ok passed, $n_fail failed, $(secs) s"
[ "$n_fail" = 0 ]
