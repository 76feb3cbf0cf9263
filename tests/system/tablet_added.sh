#!/bin/sh
# In the VM: waits (at most 60 s) until LOG says the virtual pen (or DEVICE) was added N
# times, so a script draws only once libinput reads the tablet (udev under TCG takes
# seconds, and events before that go nowhere).
#   tablet_added.sh LOG N [DEVICE]
added="${3:-edaha virtual pen} added"
i=0
while [ "$(grep -c "$added" "$1" 2>/dev/null)" -lt "$2" ] && [ $i -lt 300 ]; do
	sleep 0.2
	i=$((i + 1))
done
sleep 0.3
[ "$(grep -c "$added" "$1" 2>/dev/null)" -ge "$2" ]
