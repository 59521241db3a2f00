#!/usr/bin/env bash
# Sets up, builds, and runs the bundled default experiment (configs/default.yaml).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
cd "$root"
exec "$root/build/bin/sketchlab" run "$@"
