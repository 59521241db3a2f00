"""The python corrector plugin: a Python class run as a corrector, inside a
Python process and inside the sketchlab binary (embedded interpreter)."""
import json

import pytest

from conftest import SMALL, SNAP_ENDS_PY, run_cli


def python_stack(sl, cls, module=SNAP_ENDS_PY, **kwargs):
    return sl.stack("python", {"module": module, "class": cls, "params": json.dumps(kwargs)},
                    name=f"python-{cls}")


def test_python_snap_ends_reproduces_the_cpp_reference(sl, small):
    cpp = sl.replay(small, sl.stack("snap_ends", {"radius": 0.03}))
    py = sl.replay(small, python_stack(sl, "SnapEnds", radius=0.03))
    assert not [s.error for s in py.steps if s.error]
    # Not vacuous: ends did snap, and nodes joined curves.
    snapped = sum(s.stats.extra.get("ends_snapped", 0) for s in cpp.steps)
    assert snapped > 10 and len(cpp.sketch.network.nodes) > 10
    # The same sketch to the bit: curves, nodes, constraints per stroke.
    assert py.to_json() == cpp.to_json()
    assert [s.stats.extra for s in py.steps] == [s.stats.extra for s in cpp.steps]


def test_the_default_python_corrector_is_the_bundled_snap_ends(sl, small):
    cpp = sl.replay(small, sl.stack("snap_ends"))
    py = sl.replay(small, sl.stack("python"))
    assert py.to_json() == cpp.to_json()


def test_python_corrector_in_the_cli_matches_the_cpp_one():
    args = ["teacher-forced", SMALL, "--snap-tolerance", "1e-4"]
    code_c, out_c, err_c = run_cli(*args, "--corrector", "snap_ends")
    code_p, out_p, err_p = run_cli(*args, "--corrector", "python", "--param", f"module={SNAP_ENDS_PY}",
                                   "--param", "class=SnapEnds")
    assert code_c == 0 and code_p == 0, err_p

    def figures(out):  # everything but the timings
        return [l for l in out.splitlines() if not l.startswith(("latency", "cpu"))]

    assert figures(out_p) == figures(out_c)


def test_python_corrector_runs_in_parallel_experiments(sl, tmp_path):
    exp = tmp_path / "py.yaml"
    params = json.dumps({"module": SNAP_ENDS_PY, "class": "SnapEnds", "params": "{}"})
    exp.write_text(f"experiment: py\nrecordings: [{SMALL}, {SMALL.replace('01-2-2', '01-0-1')}]\n"
                   f"stacks: [{{corrector: snap_ends}}, {{name: py, corrector: {{plugin: python, params: {params}}}}}]\n"
                   f"outputs: {{dir: {tmp_path}/runs}}\n")
    summary = sl.experiment(exp, jobs=2, timings=False)
    assert summary.failed == 0
    rows = {(r["recording"], r["stack"]): r for r in sl.metrics_rows(summary)}
    for rec in ("01-2-2.jsonl", "01-0-1.jsonl"):
        cpp, py = rows[(rec, "snap_ends")], rows[(rec, "py")]
        keep = [k for k in cpp if not k.startswith("latency") and k != "stack"]
        assert {k: py[k] for k in keep} == {k: cpp[k] for k in keep}


BROKEN = '''
import sketchlab as sl

class Raises:
    def __init__(self, every=2):
        self.every, self.calls = every, 0
        self.fit = sl.cassie_app_preprocess()
    def correct(self, stroke, sketch):
        self.calls += 1
        if self.calls % self.every == 0:
            raise ValueError(f"boom on stroke {stroke.id}")
        return sl.freehand_edit(stroke, sketch, self.fit)

class WrongType:
    def correct(self, stroke, sketch):
        return 42

class FailsInInit:
    def __init__(self):
        raise RuntimeError("no model file")
'''


@pytest.fixture
def broken(tmp_path):
    f = tmp_path / "broken.py"
    f.write_text(BROKEN)
    return str(f)


def test_a_python_exception_becomes_the_strokes_error(sl, small, broken):
    result = sl.replay(small, python_stack(sl, "Raises", module=broken))
    strokes = [s for s in result.steps if s.event == "stroke"]
    failed = [s for s in strokes if s.error]
    assert len(failed) == len(strokes) // 2
    # One line: the exception, where it was raised (the session prefixes "corrector: ").
    assert failed[0].error == (f"corrector: python corrector {broken}:Raises: ValueError: boom on stroke "
                               f"{failed[0].stroke} (broken.py:11)")
    # The session went on: every other stroke has its curve, every raw stroke is kept.
    assert all(s.curves_added == (0 if s.error else 1) for s in strokes)
    assert len(result.sketch.strokes) == len(strokes)


def test_a_wrong_return_type_becomes_the_strokes_error(sl, small, broken):
    result = sl.replay(small, python_stack(sl, "WrongType", module=broken))
    errors = {s.error for s in result.steps if s.event == "stroke"}
    assert errors == {f"corrector: python corrector {broken}:WrongType: correct() returned int; "
                      "expected sketchlab.Correction or sketchlab.Edit"}


def test_construction_errors_name_the_class_and_the_parameter(sl, broken):
    # Building a stack reports where it was configured (here "<python>") first.
    with pytest.raises(sl.ConfigError) as err:
        python_stack(sl, "FailsInInit", module=broken)
    assert str(err.value) == (f"<python>: plugin 'python' failed to start: python corrector "
                              f"{broken}:FailsInInit: RuntimeError: no model file (broken.py:20)")
    with pytest.raises(sl.ConfigError, match="ModuleNotFoundError: No module named 'nope_no_such_module'"):
        python_stack(sl, "X", module="nope_no_such_module")
    with pytest.raises(sl.ConfigError, match="parameter 'module' is empty"):
        sl.stack("python", {"module": ""})
    with pytest.raises(sl.ConfigError, match="'params' must be a JSON object"):
        sl.stack("python", {"module": broken, "class": "WrongType", "params": "[1, 2]"})
