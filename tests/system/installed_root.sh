# shellcheck shell=bash
# Sourced by the system tests that boot systemd (vm.sh -i systemd -r ROOT), after
# gl_env.sh: the product as `meson install` lays it out, which the VM lays over its root.
#   installed_root ROOT CONF [LINE...]
# installs BUILD_ROOT into ROOT, makes CONF its /etc/edaha/edaha.conf, and gives
# edaha.service a drop-in with the LINEs (under [Service]) and guest_env. 0 or 1.
installed_root() {
	local root=$1 conf=$2 line e
	shift 2
	meson install -C "$BUILD_ROOT" --destdir "$root" --no-rebuild --quiet >/dev/null || return 1
	find "$root" -name edaha.service -path '*systemd/system/*' | grep -q . || return 1
	mkdir -p "$root/etc/edaha" "$root/etc/systemd/system/edaha.service.d" || return 1
	cp "$conf" "$root/etc/edaha/edaha.conf" || return 1
	{
		echo "[Service]"
		for line in "$@"; do echo "$line"; done
		for e in "${guest_env[@]}"; do printf 'Environment="%s"\n' "$e"; done
	} > "$root/etc/systemd/system/edaha.service.d/test.conf"
}
