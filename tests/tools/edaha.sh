# shellcheck shell=bash
# Sourced by the shell tests that run the edaha binary ($EDAHA): fail, and edaha run with
# the GL driver preloaded under ASan (EDAHA_GL_PRELOAD; tests/meson.build says why).
fail() { echo "FAIL: $*" >&2; exit 1; }
edaha() {
	if [ -n "${EDAHA_GL_PRELOAD:-}" ]; then
		LD_PRELOAD=$EDAHA_GL_PRELOAD ASAN_OPTIONS=${ASAN_OPTIONS:-}:verify_asan_link_order=0 "$EDAHA" "$@"
	else
		"$EDAHA" "$@"
	fi
}
