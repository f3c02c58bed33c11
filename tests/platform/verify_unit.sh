#!/bin/sh
# The systemd user unit as configured in the build, verified by systemd-analyze with its ExecStart pointed at the
# built lungar (the installed one is verified by scripts/check-install). Usage: verify_unit.sh UNIT LUNGAR
set -eu
unit=$1; lungar=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
mkdir -m 0700 "$work/run"
sed "s|^ExecStart=[^ ]*/lungar |ExecStart=$lungar |" "$unit" > "$work/lungar.service"
grep -q "^ExecStart=$lungar --fullscreen" "$work/lungar.service"
# --man=no: the man page is checked once installed. Any output is a finding.
out=$(XDG_RUNTIME_DIR="$work/run" systemd-analyze --user --man=no verify "$work/lungar.service" 2>&1) || { echo "$out"; exit 1; }
[ -z "$out" ] || { echo "$out"; exit 1; }
echo "systemd-analyze verify: $unit passes"
