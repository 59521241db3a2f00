"""Shared fixtures of the Python tests (run by CTest: tests/python/CMakeLists.txt
sets PYTHONPATH to the build tree's package, SKETCHLAB_SOURCE_DIR and SKETCHLAB_CLI)."""
import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("SKETCHLAB_SOURCE_DIR",
                            os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
CLI = os.environ.get("SKETCHLAB_CLI", "sketchlab")
# The smallest bundled CASSIE session with a reference track (81 events).
SMALL = os.path.join(SOURCE_DIR, "data", "recordings", "01-2-2.jsonl")
SNAP_ENDS_PY = os.path.join(SOURCE_DIR, "python", "sketchlab", "snap_ends.py")


def run_cli(*args, env=None):
    """Runs the sketchlab binary of this build; returns (exit code, stdout, stderr)."""
    p = subprocess.run([CLI, *args], capture_output=True, text=True, env=env, timeout=300)
    return p.returncode, p.stdout, p.stderr


@pytest.fixture(scope="session")
def sl():
    import sketchlab
    return sketchlab


@pytest.fixture(scope="session")
def small(sl):
    return sl.read_recording(SMALL)
