#!/bin/sh
# Run by tools/deb-test.sh inside a throw-away Debian 12 root (mmdebstrap, apt variant):
# installs edaha's package with apt, checks what it put there, upgrades it over itself
# with a changed configuration and a drawing in /var/lib/edaha, removes and purges it,
# checking each step. "ok - NAME" / "not ok - NAME" a check; "in-root: done" at the end.
#   in-root.sh DEB VERSION
# shellcheck disable=SC2016 # the sh -c scripts expand their own $(...)
set -eu
deb=$1 version=$2
export DEBIAN_FRONTEND=noninteractive
fails=0
check() { # name command...: ok when the command succeeds
	name=$1; shift
	if "$@" >/tmp/check.out 2>&1; then echo "ok - $name"
	else echo "not ok - $name"; sed 's/^/    /' /tmp/check.out; fails=$((fails + 1)); fi
}
absent() { ! "$@"; }
units="edaha.service edaha-usb.socket edaha-usb@.service"

check "no edaha user before installing" absent getent passwd edaha
check "no gpio group before installing (Debian has none)" absent getent group gpio
start=$(date +%s)
check "apt-get install ./$(basename "$deb")" apt-get install -y -q --no-install-recommends "$deb"
echo "in-root: apt-get install took $(($(date +%s) - start)) s"

# --- what the package installs ---
check "dpkg says installed $version" sh -c "dpkg-query -W -f='\${Status} \${Version}' edaha | grep -qx 'install ok installed $version'"
# the upstream version (0.1.0 of 0.1.0-1), as meson.build has it
check "edaha --version: edaha ${version%-*}" sh -c "edaha --version | grep -qx 'edaha ${version%-*}'"
check "edaha-usb-helper is installed" test -x /usr/libexec/edaha/edaha-usb-helper
for u in $units; do
	check "unit $u" test -f "/lib/systemd/system/$u"
done
check "udev rules" test -f /lib/udev/rules.d/70-edaha.rules
check "sysusers.d, tmpfiles.d" test -f /usr/lib/sysusers.d/edaha.conf -a -f /usr/lib/tmpfiles.d/edaha.conf
check "/etc/edaha/edaha.conf is a conffile" sh -c "dpkg-query -W -f='\${Conffiles}' edaha | grep -q '^ /etc/edaha/edaha.conf '"
check "the font is there (fonts-vlgothic)" test -f /usr/share/fonts/truetype/vlgothic/VL-PGothic-Regular.ttf
# systemd-analyze verify on the installed units: any output is a failure
# (tests/systemd/verify.sh does the same for meson's install)
verify() {
	out=$(systemd-analyze verify --man=no /lib/systemd/system/"$1" 2>&1) || { echo "$out"; return 1; }
	[ -z "$out" ] || { echo "$out"; return 1; }
}
for u in $units; do
	check "systemd-analyze verify $u" verify "$u"
done

# --- what the maintainer scripts did ---
check "user edaha, home /var/lib/edaha" sh -c "getent passwd edaha | grep -q ':/var/lib/edaha:'"
for g in video render input gpio; do
	check "edaha in group $g" sh -c "id -nG edaha | tr ' ' '\n' | grep -qx $g"
done
check "/var/lib/edaha/archive is edaha's, 0750" sh -c '[ "$(stat -c "%U %G %a" /var/lib/edaha /var/lib/edaha/archive | sort -u)" = "edaha edaha 750" ]'
check "edaha.service not enabled" absent test -e /etc/systemd/system/multi-user.target.wants/edaha.service
check "edaha-usb.socket not enabled" absent test -e /etc/systemd/system/sockets.target.wants/edaha-usb.socket
check "systemctl is-enabled edaha: disabled" sh -c '[ "$(systemctl is-enabled edaha.service)" = disabled ]'
check "systemctl enable edaha (as docs/deploy.md says)" systemctl enable edaha.service
check "... then enabled" test -L /etc/systemd/system/multi-user.target.wants/edaha.service

# --- upgrade over itself: the configuration as changed and the drawings stay ---
echo "# changed here" >> /etc/edaha/edaha.conf
sum=$(md5sum /etc/edaha/edaha.conf)
echo drawing > /var/lib/edaha/archive/drawing-000001.edaha
chown edaha:edaha /var/lib/edaha/archive/drawing-000001.edaha
check "upgrade (dpkg -i over itself)" dpkg -i "$deb"
check "upgrade keeps the changed edaha.conf" sh -c "echo '$sum' | md5sum -c --quiet"
check "upgrade keeps the drawings" grep -qx drawing /var/lib/edaha/archive/drawing-000001.edaha
check "upgrade keeps edaha enabled" test -L /etc/systemd/system/multi-user.target.wants/edaha.service

# --- remove: the configuration, drawings and user stay ---
check "apt-get remove edaha" apt-get remove -y -q edaha
check "remove takes the binary" absent test -e /usr/bin/edaha
check "remove takes the units" absent test -e /lib/systemd/system/edaha.service
check "remove keeps edaha.conf" test -f /etc/edaha/edaha.conf
check "remove keeps the drawings" test -f /var/lib/edaha/archive/drawing-000001.edaha
check "remove keeps the user" getent passwd edaha

# --- purge: what installing added goes ---
check "apt-get purge edaha" apt-get purge -y -q edaha
check "purge takes /etc/edaha" absent test -e /etc/edaha
check "purge takes /var/lib/edaha" absent test -e /var/lib/edaha
check "purge takes the user edaha" absent getent passwd edaha
check "purge takes the group edaha" absent getent group edaha
check "purge takes the group gpio it made" absent getent group gpio
check "purge takes the enable links" sh -c '! ls /etc/systemd/system/*.wants/edaha* 2>/dev/null | grep -q .'
check "dpkg forgot edaha" absent sh -c "dpkg-query -W -f='\${Status}' edaha 2>/dev/null | grep -q installed"

echo "in-root: $fails failed"
[ "$fails" = 0 ] || exit 1
echo "in-root: done"
