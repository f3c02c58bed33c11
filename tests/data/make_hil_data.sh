#!/usr/bin/env bash
# Regenerates the hardware-in-the-loop test data: the small baked asset and the expected per-frame output of
# tests/platform/hil_replay_vs_hid_test.cpp for upright_to_supine.trk (made by make_tracker_data.sh).
# Usage: tests/data/make_hil_data.sh [BUILD_DIR]   (default: build; builds what it needs)
#   hil_lungs.lungbake          the procedural pair, 2000 nodes, seed 7, 4 bands
#   upright_to_supine.hil.csv   per patient report: orientation, gravity, force SH, deformed-position checksums
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
cmake --build "$build" --target lungar-bake lungar_hil_tests >/dev/null
"$build/sim/lungar-bake" --procedural --nodes 2000 --seed 7 --bands 4 --out "$here/hil_lungs.lungbake"
LUNGAR_HIL_REGENERATE=1 "$here/../drivers/umockdev_run.sh" "$build/tests/platform/lungar_hil_tests" \
  --gtest_filter='HardwareInTheLoop.*'
echo "wrote $here/hil_lungs.lungbake and $here/upright_to_supine.hil.csv"
