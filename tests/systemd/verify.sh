#!/bin/bash
# The service as meson installs it: edaha.service (and every other unit of ours) passes
# `systemd-analyze verify` with not a word printed, sysusers and tmpfiles apply to a
# root holding Debian's users. Run by meson with BUILD_ROOT set.
set -euo pipefail

skip() { echo "SKIP: $*"; exit 77; }
command -v systemd-analyze >/dev/null || skip "no systemd-analyze (apt-get install systemd)"
[ -d /lib/systemd/system ] || skip "no /lib/systemd/system to verify against"

root=$(mktemp -d /tmp/edaha-verify.XXXXXX)
trap 'rm -rf "$root"' EXIT
meson install -C "$BUILD_ROOT" --destdir "$root" --no-rebuild --quiet >/dev/null
prefix=$(meson introspect "$BUILD_ROOT" --buildoptions |
	python3 -c 'import json,sys; print(next(o["value"] for o in json.load(sys.stdin) if o["name"] == "prefix"))')
# what the units name (sysinit.target, seatd.service, getty@.service) comes from the host
mkdir -p "$root/lib/systemd" "$root/etc"
cp -a /lib/systemd/system "$root/lib/systemd/"
cp /etc/passwd /etc/group "$root/etc/"

fail=0
shopt -s nullglob
units=()
for u in "$root$prefix"/lib/systemd/system/*.{service,socket}; do units+=("${u#"$root"}"); done
[ ${#units[@]} -gt 0 ] || { echo "FAIL: no units installed under $prefix/lib/systemd/system"; exit 1; }
for u in "${units[@]}"; do
	# verify exits 0 on settings it ignores: any output is a failure
	out=$(systemd-analyze verify --root="$root" --man=no "$u" 2>&1) || { echo "$out"; fail=1; }
	if [ -n "$out" ]; then
		echo "FAIL: $u:"; echo "$out"; fail=1
	else
		echo "ok: $u"
	fi
done
[ -x "$root$prefix/bin/edaha" ] || { echo "FAIL: no $prefix/bin/edaha"; fail=1; }
grep -q "^ExecStart=$prefix/bin/edaha" "$root$prefix/lib/systemd/system/edaha.service" ||
	{ echo "FAIL: edaha.service does not start $prefix/bin/edaha"; fail=1; }

out=$(systemd-sysusers --root="$root" --dry-run 2>&1) || { echo "$out"; fail=1; }
echo "$out" | grep -q "Creating user 'edaha'" || { echo "FAIL: sysusers makes no edaha user:"; echo "$out"; fail=1; }
echo "$out" | grep -q "Creating group 'gpio'" || { echo "FAIL: sysusers makes no gpio group:"; echo "$out"; fail=1; }
systemd-sysusers --root="$root" >/dev/null
for g in video render input gpio; do
	grep -q "^$g:.*[:,]edaha\(,\|$\)" "$root/etc/group" || { echo "FAIL: edaha not in group $g"; fail=1; }
done
out=$(systemd-tmpfiles --root="$root" --create 2>&1) || { echo "$out"; fail=1; }
[ -d "$root/var/lib/edaha/archive" ] || { echo "FAIL: tmpfiles made no /var/lib/edaha/archive"; fail=1; }
uid=$(awk -F: '$1 == "edaha" { print $3 }' "$root/etc/passwd")
[ -n "$uid" ] && [ "$(stat -c %u "$root/var/lib/edaha")" = "$uid" ] || { echo "FAIL: /var/lib/edaha not edaha's"; fail=1; }
[ $fail = 0 ] && echo "systemd-verify: all units, sysusers and tmpfiles fine"
exit $fail
