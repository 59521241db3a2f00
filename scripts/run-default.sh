#!/usr/bin/env bash
# Sets up, builds and runs the bundled default experiment (configs/default.yaml,
# or the experiment and overrides given). Only what the run needs is built:
# the CLI target, which depends on every plugin and the viewer it draws
# pictures with; the tests and benchmarks are left to scripts/test.sh.
# Pictures need an X display (Debian's VTK renders offscreen through X only):
# without one, the run goes through xvfb-run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/build.sh" sketchlab_cli
cd "$root"
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  exec xvfb-run -a "$root/build/bin/sketchlab" run "$@"
fi
exec "$root/build/bin/sketchlab" run "$@"
