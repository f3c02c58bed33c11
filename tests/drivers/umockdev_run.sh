#!/bin/sh
# Runs a test binary under umockdev-wrapper (the emulated hidraw tracker needs its LD_PRELOAD library).
# Under AddressSanitizer the preload comes before ASan's runtime, which ASan refuses by default; the order is
# harmless here (umockdev wraps device calls, ASan wraps memory), so that check alone is turned off.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"
export ASAN_OPTIONS
exec umockdev-wrapper "$@"
