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
# uinput_pen's `sh $ARCHIVED_KILL` (forest.script): the second visitor's drawing is
# archived by the idle reset; the kiosk is killed at once, while it plants it
if [ "$1" = archived-kill ]; then
	i=0
	while [ ! -s /var/lib/edaha/archive/drawing-000002.edaha ] && [ $i -lt 1200 ]; do
		sleep 0.05
		i=$((i + 1))
	done
	systemctl kill -s KILL edaha.service
	grep -q 'No. 2 planted' /out/edaha.log && echo "planted before the kill" > /out/kill-planting.txt ||
		echo "killed mid-planting" > /out/kill-planting.txt
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

# a known clock: today's forest begins its day at 04:00 (forest.reset_at), which the test
# must not cross by chance; step 6 crosses it on purpose
date -s "2026-12-05 12:00:00" > /dev/null
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
sleep 5 # "Your tree is No. 1 in today's forest" shows for 4 s
"$scanout" /dev/dri/card0 /out/after-reset.png 2>> /out/scanout.err || say "no scanout"
mkdir -p /out/archive && cp /var/lib/edaha/archive/* /out/archive/ 2>/dev/null
phase "reset"

# 5. today's forest: the attract screen (after 3 s) shows the day's trees; a second
# visitor's drawing is archived and the kiosk killed while it plants it: back, both stand
sed -i 's/attract_after: 0/attract_after: 3/' /etc/edaha/edaha.conf
systemctl restart edaha.service || say "no restart"
wait_for grep -q 'trees standing (No. 1 to 1)' /out/edaha.log || say "no forest of one"
sleep 8
"$scanout" /dev/dri/card0 /out/forest-1.png 2>> /out/scanout.err || say "no scanout"
phase "the forest of one"
export ARCHIVED_KILL="$0 archived-kill"
export PEN_READY="$H/tablet_added.sh /out/edaha.log $(($(grep -c 'edaha virtual pen added' /out/edaha.log) + 1))"
pid=$(show MainPID)
UINPUT_PEN_WAIT_MS=0 "$pen" < "$H/forest.script" 2>> /out/pen.err || say "uinput_pen failed"
other() { [ "$(show MainPID)" != "$pid" ] && [ "$(show MainPID)" != 0 ] && [ "$(show ActiveState)" = active ]; }
wait_for other || say "not restarted after the SIGKILL mid-planting"
wait_for grep -q 'trees standing (No. 1 to 2)' /out/edaha.log || say "no forest of two"
sleep 8
"$scanout" /dev/dri/card0 /out/forest-2.png 2>> /out/scanout.err || say "no scanout"
cp /var/lib/edaha/forest-day /out/forest-day-1 2>/dev/null
phase "the forest of two, after a SIGKILL mid-planting"

# 6. the reset hour (forest.reset_at, 04:00) passes: the clock set a day on, as NTP would
# step it; the realtime timer wakes the kiosk at once: a new day, the forest empty
date -s tomorrow > /out/date.txt
wait_for sh -c "[ \"\$(grep -c 'a new day' /out/edaha.log)\" -ge 2 ]" || say "no new day"
sleep 4
"$scanout" /dev/dri/card0 /out/forest-day.png 2>> /out/scanout.err || say "no scanout"
cp /var/lib/edaha/forest-day /out/forest-day-2 2>/dev/null
phase "a new day"
systemctl stop edaha.service
sleep 1
journalctl -u edaha.service -o cat --no-pager > /out/edaha.log
exit 0
