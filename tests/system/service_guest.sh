#!/bin/sh
# The guest half of service.sh, run by systemd (vm.sh -i systemd) on a root with edaha
# installed by meson: edaha.service started as the product starts it, then killed and
# stalled. Writes to /out: edaha.log (its journal), status-*.txt, *.png (what the
# display scans out), drawing.journal, archive/.
#   service_guest.sh UINPUT_PEN SCANOUT KMOD_DIR
records() { [ "$(grep -c '^@ ' /var/lib/edaha/drawing.journal 2>/dev/null)" -ge "$1" ]; }
# uinput_pen's `sh $SAVED` comes back here: the two strokes are in the journal, and the
# screen shows them
if [ "$1" = saved ]; then
	i=0
	while ! records 3 && [ $i -lt 300 ]; do sleep 0.2; i=$((i + 1)); done
	sleep 2
	"$2" /dev/dri/card0 /out/before-kill.png 2>> /out/scanout.err
	exit 0
fi
pen=$1 scanout=$2 kmod=$3
H=$(dirname "$0")
say() { echo "service_guest: $*"; }
phase() { echo "$(cut -d' ' -f1 /proc/uptime) s: $*" >> /out/phases.txt; }
show() { systemctl show edaha.service -p "$1" --value; }
# the journal of the unit, as a file the waits can grep
journalctl -f -o cat -u edaha.service > /out/edaha.log 2>&1 &
wait_for() { # COMMAND... : at most 90 s
	i=0
	while ! "$@" && [ $i -lt 450 ]; do sleep 0.2; i=$((i + 1)); done
	"$@"
}
restarted() { [ "$(show NRestarts)" -ge "$1" ] && [ "$(show ActiveState)" = active ]; }
backs() { [ "$(grep -c 'the drawing is back' /out/edaha.log)" -ge "$1" ]; }

modprobe uinput || exit 3
"$H/gpio_sim.sh" setup "$kmod" || exit 3
udevadm settle -t 30
ls -l /dev/gpiochip* > /out/gpiochips.txt
getent passwd edaha > /out/user.txt && id edaha >> /out/user.txt

phase "booted, gpio-sim up"
# 1. started as at boot: `systemctl start` returns once the kiosk said READY=1
t0=$(cut -d' ' -f1 /proc/uptime)
systemctl start edaha.service || { say "edaha.service did not start"; systemctl status edaha --no-pager; }
t1=$(cut -d' ' -f1 /proc/uptime)
echo "ready after $(echo "$t1 - $t0" | bc) s" > /out/ready.txt
systemctl show edaha.service -p ActiveState -p SubState -p MainPID -p NRestarts -p User \
	-p WatchdogUSec -p Type > /out/status-start.txt
pid=$(show MainPID)
ps -o user=,group=,supgrp= -p "$pid" > /out/proc.txt
grep -E '^(Cap(Eff|Prm|Bnd)|NoNewPrivs|Seccomp):' /proc/"$pid"/status >> /out/proc.txt

phase "ready"
# 2. drawn on with the pen; killed with SIGKILL in the middle of the third stroke
export TABLET_ADDED="$H/tablet_added.sh /out/edaha.log"
export SAVED="$0 saved $scanout"
export KILL="systemctl kill -s KILL edaha.service"
UINPUT_PEN_WAIT_MS=0 "$pen" < "$H/service.script" 2> /out/pen.err || say "uinput_pen failed"
wait_for restarted 1 || say "not restarted after SIGKILL"
wait_for backs 1 || say "the drawing did not come back after SIGKILL"
sleep 3 # its first frames
"$scanout" /dev/dri/card0 /out/after-kill.png 2> /out/scanout.err || say "no scanout"
systemctl show edaha.service -p NRestarts -p MainPID -p Result > /out/status-kill.txt

phase "back after SIGKILL"
# 3. the main loop stalls (SIGSTOP): the watchdog notices, systemd restarts it
pid=$(show MainPID)
kill -STOP "$pid"
wait_for restarted 2 || say "not restarted after the stall"
wait_for backs 2 || say "the drawing did not come back after the watchdog restart"
sleep 3
"$scanout" /dev/dri/card0 /out/after-watchdog.png 2>> /out/scanout.err || say "no scanout"
systemctl show edaha.service -p NRestarts -p MainPID -p Result > /out/status-watchdog.txt
journalctl -u edaha.service -o cat --no-pager | grep -i watchdog > /out/watchdog.txt
cp /var/lib/edaha/drawing.journal /out/ 2>/dev/null

phase "back after the watchdog"
# 4. nobody draws for reset_after: archived, and a clean canvas
sed -i 's/reset_after: 0/reset_after: 4/' /etc/edaha/edaha.conf
systemctl restart edaha.service || say "no restart"
wait_for grep -q 'a new canvas' /out/edaha.log || say "no idle reset"
sleep 2
"$scanout" /dev/dri/card0 /out/after-reset.png 2>> /out/scanout.err || say "no scanout"
mkdir -p /out/archive && cp /var/lib/edaha/archive/* /out/archive/ 2>/dev/null
phase "reset"
systemctl stop edaha.service
sleep 1
journalctl -u edaha.service -o cat --no-pager > /out/edaha.log
exit 0
