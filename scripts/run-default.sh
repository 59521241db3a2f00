#!/usr/bin/env bash
# Sets up, builds, and runs the bundled default experiment (configs/default.yaml).
# Pictures need an X display: without one, the run goes through xvfb-run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
cd "$root"
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  exec xvfb-run -a "$root/build/bin/sketchlab" run "$@"
fi
exec "$root/build/bin/sketchlab" run "$@"
