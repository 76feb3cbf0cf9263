# shellcheck shell=bash
# Sourced by the shell tests that need an X display (the desktop window, Firefox's WebGL):
# xvfb_start DIR WxH starts Xvfb on a free display number (Xvfb picks it: -displayfd),
# its log DIR/xvfb.log; sets XVFB (its pid, for the caller's cleanup to kill) and
# XVFB_DISPLAY (":N"). Returns 1, the log printed, when it did not start.
xvfb_start() {
	local dir=$1 size=$2
	exec 3>"$dir/display"
	Xvfb -displayfd 3 -screen 0 "${size}x24" -nolisten tcp >"$dir/xvfb.log" 2>&1 &
	XVFB=$!
	for _ in $(seq 100); do [ -s "$dir/display" ] && break; sleep 0.1; done
	exec 3>&-
	[ -s "$dir/display" ] || { cat "$dir/xvfb.log" >&2; return 1; }
	XVFB_DISPLAY=:$(cat "$dir/display")
}
