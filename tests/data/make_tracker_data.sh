#!/usr/bin/env bash
# Regenerates the committed tracker test data from the mock trajectories (libsurvive-style: small logs in git,
# their expected poses beside them, both made by one command).
# Usage: tests/data/make_tracker_data.sh [BUILD_DIR]   (default: build; needs the lungar-trk target built)
#   upright_to_supine.trk           6 s of the patient turning upright -> supine, head in front, 62.5 Hz per
#                                   sensor, the default layout of config/default.toml (32-byte reports,
#                                   station byte: head = 1, patient = 2); 750 records
#   upright_to_supine.expected.csv  lungar-trk dump of it: every pose the decoder must produce
#   head_orbit_noisy.trk            3 s of the head orbit with 0.5 mm noise and 5 % dropped reports
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
trk=$build/drivers/lungar-trk
[ -x "$trk" ] || { echo "make_tracker_data.sh: $trk: expected the built lungar-trk (cmake --build $build --target lungar-trk)" >&2; exit 1; }
"$trk" synth "$here/upright_to_supine.trk" --trajectory upright_to_supine --seconds 6 --rate-hz 62.5
"$trk" dump "$here/upright_to_supine.trk" --format csv > "$here/upright_to_supine.expected.csv.partial"
mv "$here/upright_to_supine.expected.csv.partial" "$here/upright_to_supine.expected.csv"
"$trk" synth "$here/head_orbit_noisy.trk" --trajectory head_orbit --seconds 3 --rate-hz 62.5 --noise-mm 0.5 --dropout 0.05
