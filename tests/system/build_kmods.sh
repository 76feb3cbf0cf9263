#!/bin/bash
# Builds gpio-sim (with the irq_sim it needs) as an out-of-tree module for the kernel the
# VM boots: Debian 12's kernel ships without it (CONFIG_GPIO_SIM and CONFIG_IRQ_SIM are
# unset). The sources come from Debian's linux-source-6.1, built against
# linux-headers-$KVER; the module lands in $OUT/gpio-sim/gpio-sim-oot.ko, and a second
# call with the same kernel and sources does nothing.
#   build_kmods.sh OUT
# Exit 77 (skip) when the sources or headers are missing, with what to install.
# Packages: linux-source-6.1 linux-headers-amd64 make gcc xz-utils bc.
set -euo pipefail
out=${1:?usage: build_kmods.sh OUT}
kver=${KVER:-$(ls /lib/modules 2>/dev/null | sort -V | tail -1)}
kbuild=/lib/modules/$kver/build
tarball=$(ls /usr/src/linux-source-*.tar.xz 2>/dev/null | sort -V | tail -1 || true)
skip() { echo "build_kmods: SKIP: $*"; exit 77; }
[ -n "$tarball" ] || skip "no /usr/src/linux-source-*.tar.xz (apt-get install linux-source-6.1)"
[ -d "$kbuild" ] || skip "no $kbuild (apt-get install linux-headers-$kver)"
ko=$out/gpio-sim/gpio-sim-oot.ko
stamp="$kver $(stat -c %Y "$tarball") $(stat -c %Y "$0")"
if [ -f "$ko" ] && [ "$(cat "$out/gpio-sim/stamp" 2>/dev/null)" = "$stamp" ]; then
	exit 0
fi
rm -rf "$out/gpio-sim" "$out/src"
mkdir -p "$out/gpio-sim" "$out/src"
top=$(basename "$tarball" .tar.xz) # linux-source-6.1, as the tarball names its top folder
tar -xJf "$tarball" -C "$out/src" "$top/drivers/gpio/gpio-sim.c" "$top/drivers/gpio/gpiolib.h" \
	"$top/kernel/irq/irq_sim.c"
cp "$out/src/$top/drivers/gpio/gpio-sim.c" "$out/src/$top/drivers/gpio/gpiolib.h" \
	"$out/src/$top/kernel/irq/irq_sim.c" "$out/gpio-sim/"
rm -rf "$out/src"
# irq_to_desc() is not exported to modules; generic_handle_irq() runs the same flow handler
sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' "$out/gpio-sim/irq_sim.c"
grep -q 'generic_handle_irq(irqnum);' "$out/gpio-sim/irq_sim.c" ||
	{ echo "build_kmods: irq_sim.c changed; the module patch no longer applies" >&2; exit 1; }
printf 'obj-m += gpio-sim-oot.o\ngpio-sim-oot-y := gpio-sim.o irq_sim.o\n' > "$out/gpio-sim/Makefile"
make -s -C "$kbuild" M="$out/gpio-sim" modules >"$out/gpio-sim/build.log" 2>&1 ||
	{ cat "$out/gpio-sim/build.log" >&2; exit 1; }
strip --strip-debug "$ko"
echo "$stamp" > "$out/gpio-sim/stamp"
echo "build_kmods: built $ko for $kver"
