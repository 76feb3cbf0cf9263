#!/bin/bash
# Runs COMMAND where programs built for ARCH run through qemu-user, as mmdebstrap needs to
# make a root filesystem of another architecture (it runs the packages' maintainer scripts):
#
#   images/foreign.sh ARCH COMMAND [ARGS...]
#
# - ARCH's programs already run (the machine's own architecture, or binfmt_misc already
#   knows qemu-user's interpreter, as on a Debian desktop with qemu-user-static and
#   binfmt-support): COMMAND runs as it is.
# - Otherwise (a container, where qemu-user-static registers nothing): COMMAND runs as root
#   in a user namespace of its own (uid and gid 0.. mapped onto themselves, so files keep
#   their owners) with a private binfmt_misc that knows qemu-ARCH-static. Linux 6.7 or
#   later; nothing is registered machine-wide, and it all ends with COMMAND.
# Packages: qemu-user-static arch-test util-linux.
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: foreign.sh ARCH COMMAND [ARGS...]" >&2; exit 2; }
arch=$1; shift

runs() { [ "$arch" = "$(dpkg --print-architecture)" ] || arch-test "$arch" >/dev/null 2>&1; }

if [ "${EDAHA_FOREIGN_NS:-}" = 1 ]; then
	# inside the namespace: our own /proc and binfmt_misc, then the command
	mount -t proc proc /proc
	mount -t binfmt_misc binfmt_misc /proc/sys/fs/binfmt_misc ||
		{ echo "foreign: binfmt_misc cannot be mounted in a user namespace here (needs Linux 6.7 or later)" >&2; exit 1; }
	conf=/usr/lib/binfmt.d/qemu-$qarch.conf
	# its flags have F: the kernel opens the interpreter now, so it runs inside any chroot
	cat "$conf" > /proc/sys/fs/binfmt_misc/register
	runs || { echo "foreign: $arch programs still do not run (qemu-$qarch-static)" >&2; exit 1; }
	unset EDAHA_FOREIGN_NS qarch
	exec "$@"
fi

command -v arch-test >/dev/null || { echo "foreign: no arch-test (apt-get install arch-test)" >&2; exit 1; }
runs && exec "$@"

case $arch in
arm64) qarch=aarch64 ;;
armhf) qarch=arm ;;
*) qarch=$arch ;;
esac
[ -x "/usr/bin/qemu-$qarch-static" ] && [ -r "/usr/lib/binfmt.d/qemu-$qarch.conf" ] ||
	{ echo "foreign: $arch programs do not run here and there is no qemu-$qarch-static (apt-get install qemu-user-static)" >&2; exit 1; }
[ "$(id -u)" = 0 ] || { echo "foreign: $arch programs do not run here; a private binfmt_misc needs root" >&2; exit 1; }

# The namespace is made by unshare; its uid and gid maps are written from out here (as root
# may), then the child is let go through a fifo.
go=$(mktemp -u "${TMPDIR:-/tmp}/edaha-foreign.XXXXXX")
mkfifo "$go"
trap 'rm -f "$go"' EXIT
export EDAHA_FOREIGN_NS=1 qarch
unshare --user --mount --pid --fork --kill-child -- sh -c 'read -r _ < "$0"; exec "$@"' \
	"$go" "$(realpath "$0")" "$arch" "$@" &
ns=$!
for _ in $(seq 50); do
	[ "$(readlink "/proc/$ns/ns/user")" != "$(readlink /proc/self/ns/user)" ] && break
	sleep 0.1
done
echo "0 0 4294967295" > "/proc/$ns/uid_map"
echo "0 0 4294967295" > "/proc/$ns/gid_map"
echo go > "$go"
rc=0
wait "$ns" || rc=$?
exit $rc
