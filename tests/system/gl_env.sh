# shellcheck shell=bash
# Sourced by the system tests that run edaha: the environment for edaha on the host
# (host_env) and in the guest (guest_env). Under ASan the GL driver is preloaded into
# edaha only (see tests/meson.build, EDAHA_GL_PRELOAD); the guest gets the same, as it
# runs the host's files. llvmpipe's 256-bit vectors are slow under TCG; 128-bit ones
# halve the frame time there.
guest_env=(LP_NATIVE_VECTOR_WIDTH=128)
host_env=()
if [ -n "${EDAHA_GL_PRELOAD:-}" ]; then
	host_env=(LD_PRELOAD="$EDAHA_GL_PRELOAD" ASAN_OPTIONS="${ASAN_OPTIONS:-}:verify_asan_link_order=0")
	guest_env+=("${host_env[@]}" UBSAN_OPTIONS="${UBSAN_OPTIONS:-}" LSAN_OPTIONS="${LSAN_OPTIONS:-}")
fi
