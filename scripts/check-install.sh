#!/usr/bin/env bash
# The installed SDK as a new user meets it (docs/plugin-authoring.md,
# docs/python.md): installs a build (default build/) into a clean prefix,
# builds examples/plugin out of tree against it with find_package only (and
# another build type: the fingerprint comes from the installed header), loads
# it into the installed binary and runs it on a bundled session, installs it
# into the prefix, builds a program with the pkg-config file, and imports the
# installed Python package from outside the source tree.
# Usage: scripts/check-install.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
step() { echo "check-install: $*"; }
fail() { echo "check-install: FAILED: $*" >&2; exit 1; }

step "install $build into a clean prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
[ -f "$prefix/lib/cmake/sketchlab/sketchlabConfig.cmake" ] || fail "no CMake package installed"
[ -f "$prefix/include/sketchlab/build_config.hpp" ] || fail "no build_config.hpp installed"
[ ! -e "$prefix/lib/sketchlab/plugins/sketchlab_corrector_snap_ends.so" ] ||
  fail "the example plugin is installed by the main build (it would shadow the user's)"

step "build examples/plugin out of tree against the prefix"
cmake -S "$root/examples/plugin" -B "$work/plugin" "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/plugin" >/dev/null
plugin_dir=$work/plugin/lib/sketchlab/plugins
[ -f "$plugin_dir/sketchlab_corrector_snap_ends.so" ] || fail "the plugin was not built in $plugin_dir"

step "load it into the installed sketchlab and run it on a bundled session"
sketchlab=$prefix/bin/sketchlab
session=$prefix/share/sketchlab/data/recordings/01-2-2.jsonl
if "$sketchlab" plugins snap_ends >/dev/null 2>&1; then
  fail "the installed sketchlab found snap_ends before it was built (build tree searched?)"
fi
out=$(cd "$work" && SKETCHLAB_PLUGIN_PATH=$plugin_dir "$sketchlab" plugins snap_ends 2>&1) ||
  fail "snap_ends did not load: $out"
case "$out" in *warning*) fail "warnings while loading: $out" ;; esac
out=$(cd "$work" && SKETCHLAB_PLUGIN_PATH=$plugin_dir "$sketchlab" teacher-forced "$session" \
      --corrector snap_ends 2>&1) || fail "teacher-forced with snap_ends: $out"
grep -q '^compared [1-9]' <<<"$out" || fail "no stroke compared: $out"

step "install it into the prefix; the installed sketchlab finds it there"
cmake --install "$work/plugin" --prefix "$prefix" >/dev/null
(cd "$work" && "$sketchlab" plugins snap_ends >/dev/null) || fail "installed plugin not found"

step "build a program with pkg-config"
cat >"$work/fingerprint.cpp" <<'CPP'
#include <cstdio>
#include <cstring>
#include "sketchlab/version.hpp"
int main() {
  // The header's fingerprint (what a plugin built here records) is the
  // installed kernel's.
  std::printf("%s\n", sketchlab::build_fingerprint());
  return std::strcmp(SKETCHLAB_BUILD_FINGERPRINT, sketchlab::build_fingerprint()) == 0 ? 0 : 1;
}
CPP
flags=$(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --cflags --libs sketchlab)
# shellcheck disable=SC2086
c++ "$work/fingerprint.cpp" -o "$work/fingerprint" $flags -Wl,-rpath,"$prefix/lib"
"$work/fingerprint" >/dev/null || fail "fingerprint of a pkg-config build differs from the kernel's"

python_dir=$(find "$prefix/lib" -maxdepth 3 -type d -name dist-packages | head -n 1)
# A sanitizer build's module is instrumented and Debian's python3 is not: the
# sanitizers' runtimes are preloaded, and CPython's memory at exit is not a
# leak (tests/python/CMakeLists.txt does the same).
python=(/usr/bin/python3)
if grep -q '+asan' "$prefix/include/sketchlab/build_config.hpp"; then
  python=(env "LD_PRELOAD=$(c++ -print-file-name=libasan.so) $(c++ -print-file-name=libubsan.so)"
          ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 /usr/bin/python3)
fi
if [ -n "$python_dir" ]; then
  step "import the installed Python package and run the example plugin from it"
  (cd "$work" && SKETCHLAB_PLUGIN_PATH= PYTHONPATH=$python_dir "${python[@]}" - "$prefix" "$session" <<'PY'
import sys, sketchlab as sl
prefix, session = sys.argv[1], sys.argv[2]
assert sl.__file__.startswith(prefix), sl.__file__
names = {p.name for p in sl.plugins("corrector")}
assert {"cassie", "snap_ends", "python"} <= names, names
assert all(str(p.path).startswith(prefix) for p in sl.host().plugins), "plugins from outside the prefix"
r = sl.replay(sl.read_recording(session), sl.stack("snap_ends"))
assert len(r.sketch.network.nodes) > 0
PY
  ) || fail "the installed Python package"
  step "the installed sketchlab runs a Python corrector (embedded interpreter; by default the"
  step "installed package's sketchlab.snap_ends)"
  out=$(cd "$work" && "$sketchlab" teacher-forced "$session" --corrector python 2>&1) ||
    fail "python corrector in the installed binary: $out"
  grep -q '^errors 0' <<<"$out" || fail "python corrector errors: $out"
fi
step "ok"
