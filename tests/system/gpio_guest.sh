#!/bin/sh
# The guest half of gpio.sh: input_probe with gpio.conf, buttons pressed through gpio-sim.
# $1 input_probe, $2 the kmod dir. Writes /out/probe.trace, /out/probe.err, /out/leds.
H=$(dirname "$0")
"$H/gpio_sim.sh" setup "$2" || exit 3
"$1" --config "$H/gpio.conf" --seconds 40 >/out/probe.trace 2>/out/probe.err &
sleep 4
"$H/gpio_sim.sh" press 0; sleep 0.5
echo "after-3d $("$H/gpio_sim.sh" value 5) $("$H/gpio_sim.sh" value 6)" >>/out/leds
"$H/gpio_sim.sh" release 0; sleep 1.5
# a press and release within debounce_ms (1000): the release is dropped at its edge
# and read from the line when the window closes
"$H/gpio_sim.sh" press 1; sleep 0.2; "$H/gpio_sim.sh" release 1; sleep 1.5
echo "after-clone $("$H/gpio_sim.sh" value 5) $("$H/gpio_sim.sh" value 6)" >>/out/leds
"$H/gpio_sim.sh" press 3; sleep 1.5; "$H/gpio_sim.sh" release 3; sleep 1.5
# a bouncing press: press, release, press within the window: one press, no release
"$H/gpio_sim.sh" bounce 2; sleep 2
kill $! 2>/dev/null
wait
