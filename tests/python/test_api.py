"""The Python API wraps the kernel: recordings, strokes, plugins, stacks,
sessions with undo, replays, experiments, the teacher-forced comparison, and
errors with the command line's messages."""
import threading
import time

import numpy as np
import pytest

from conftest import SMALL, SOURCE_DIR, run_cli


def test_plugins_and_their_parameter_specs(sl):
    names = {p.name for p in sl.plugins("corrector")}
    assert {"cassie", "freehand", "snap_ends", "python"} <= names
    freehand = sl.host().find(sl.PluginKind.corrector, "freehand")
    delta = next(s for s in freehand.params if s.name == "delta")
    assert delta.type == sl.ParamType.real and delta.default == 0.02 and delta.unit == "m"
    assert delta.allowed.startswith("real in [0.001, 0.5]")


def test_recording_round_trip_and_events(sl, small, tmp_path):
    types = [e.type for e in small]
    assert types.count("stroke") == len(small.strokes()) > 0 and "reference" in types
    first = next(e for e in small if e.type == "stroke")
    d = first.to_dict()
    assert d["type"] == "stroke" and d["id"] == first.stroke.id
    assert first.stroke.points.shape == (len(d["samples"]), 3)
    assert sl.Event.from_json(first.to_json()) == first
    out = tmp_path / "copy.jsonl"
    sl.write_recording(out, small)
    assert out.read_bytes() == open(SMALL, "rb").read()  # read-then-write is byte-identical
    assert sl.read_recording(out) == small
    with pytest.raises(RuntimeError, match="exists"):
        sl.write_recording(out, small)


def test_recording_errors_carry_the_cli_message(sl, tmp_path):
    bad = tmp_path / "bad.jsonl"
    bad.write_text(open(SMALL).readline() + '{"t":0,"type":"jump"}\n')
    with pytest.raises(sl.RecordingError) as err:
        sl.read_recording(bad)
    assert str(err.value).startswith(f"{bad}:2: ")
    code, _, stderr = run_cli("teacher-forced", str(bad), "--corrector", "freehand")
    assert code == 1 and stderr.strip() == f"sketchlab: {err.value}"


def test_parameter_errors_carry_the_cli_message(sl):
    with pytest.raises(sl.ConfigError) as err:
        sl.stack("freehand", {"delta": 7.0})
    assert "delta" in str(err.value) and "real in [0.001, 0.5]" in str(err.value)
    with pytest.raises(sl.PluginError) as err:
        sl.corrector("no_such_corrector")
    code, _, stderr = run_cli("teacher-forced", SMALL, "--corrector", "no_such_corrector")
    assert code == 1 and stderr.strip() == f"sketchlab: {err.value}"


def test_strokes_from_numpy_and_a_live_session_with_undo(sl):
    s = np.linspace(0.0, 1.0, 40)
    line = sl.Stroke(1, np.column_stack([0.3 * s, np.zeros_like(s), np.zeros_like(s)]))
    arc = sl.Stroke(2, np.column_stack([0.3 * s, 0.1 * np.sin(np.pi * s), np.zeros_like(s)]),
                    times=1.0 + 0.01 * np.arange(40))
    assert line.points.shape == (40, 3) and np.allclose(arc.times[0], 1.0)
    with pytest.raises(ValueError, match="shape"):
        sl.Stroke(3, np.zeros((5, 2)))
    session = sl.Session(sl.stack("freehand"))
    for stroke in (line, arc):
        report = session.handle(sl.Event.of_stroke(stroke))
        assert report.error == "" and report.curves_added == 1
    curves = session.sketch.network.curves
    assert len(curves) == 2
    c = curves[2].curve
    assert c.control_points.shape == (3 * c.segment_count + 1, 3)
    assert c.sample(16).shape == (16, 3)
    assert np.allclose(c.sample(16)[0], arc.points[0], atol=1e-9)
    session.handle(sl.Event.undo(2.0))
    assert list(session.sketch.network.curves) == [1]
    session.handle(sl.Event.redo(2.1))
    assert len(session.sketch.network.curves) == 2
    # Stepping back: before the redo, before the undo, before stroke 2.
    assert session.revert_last() and list(session.sketch.network.curves) == [1]
    assert session.revert_last() and list(session.sketch.network.curves) == [1, 2]
    assert session.revert_last() and list(session.sketch.network.curves) == [1]
    assert session.events_handled == 1


def test_live_session_records_what_it_folds(sl, small, tmp_path):
    path = tmp_path / "live.jsonl"
    live = sl.LiveSession(small.header, [sl.stack("freehand")], path)
    for e in list(small)[:10]:
        live.handle(e)
    live.close()
    again = sl.read_recording(path)
    assert again.events == list(small)[:10]
    replayed = sl.replay(again, sl.stack("freehand"))
    assert replayed.session.to_json() == live.session(0).to_json()


def test_replay_matches_the_cli_run_byte_for_byte(sl, small, tmp_path):
    stack = sl.stack_from_file(f"{SOURCE_DIR}/configs/stacks/cassie.yaml")
    result = sl.replay(small, stack)
    net = result.sketch.network
    assert len(net.curves) > 10 and len(net.nodes) > 0
    assert len(result.steps) == len(small)
    exp = tmp_path / "one.yaml"
    exp.write_text(f"experiment: one\nrecordings: [{SMALL}]\n"
                   "stacks: [{name: cassie, corrector: {plugin: cassie, params: {mirror: plane}}}]\n"
                   f"outputs: {{dir: {tmp_path}/runs, timestamp: false}}\n")
    code, _, stderr = run_cli("run", str(exp), "--no-timings", "-j", "1")
    assert code == 0, stderr
    written = (tmp_path / "runs" / "one" / "01-2-2" / "cassie" / "sketch.json").read_text()
    assert result.to_json() == written


def test_experiment_rows_and_two_stacks_compared(sl, tmp_path):
    exp = tmp_path / "two.yaml"
    exp.write_text(f"experiment: two\nrecordings: [{SMALL}]\n"
                   "stacks: [{corrector: {plugin: freehand}}, {corrector: {plugin: snap_ends}}]\n"
                   f"outputs: {{dir: {tmp_path}/runs}}\n")
    summary = sl.experiment(exp, ["stacks.1.corrector.params.radius=0.03"], jobs=2)
    assert summary.failed == 0
    rows = sl.metrics_rows(summary)
    assert [r["stack"] for r in rows] == ["freehand", "snap_ends"]
    # Snapping ends joins curves: fewer dangling ends than the freehand fit.
    assert rows[1]["nodes"] > rows[0]["nodes"] == 0
    assert rows[1]["dangling_endpoint_ratio"] < rows[0]["dangling_endpoint_ratio"]


def test_teacher_forced_matches_the_cli(sl, small):
    strokes = sl.teacher_forced(small, sl.corrector("snap_ends"))
    s = sl.summarize(strokes)
    assert s.strokes == len(small.strokes()) and s.compared > 0
    code, out, _ = run_cli("teacher-forced", SMALL, "--corrector", "snap_ends")
    assert code == 0
    cli = dict(line.split(" ", 1) for line in out.splitlines())
    assert int(cli["compared"]) == s.compared and int(cli["errors"]) == s.errors
    assert float(cli["snap_agreement"].split()[0]) == pytest.approx(100 * s.snap_agreement, abs=1e-3)


def test_teacher_forced_rows_hold_the_curves_compared(sl, small):
    strokes = [r for r in sl.teacher_forced(small, sl.corrector("snap_ends")) if r.compared]
    assert strokes
    drawn = {s.id: s for s in small.strokes()}
    for r in strokes:
        ref, out = r.reference_curve, r.output_curve
        # The row's end distance is the one between these two curves' ends.
        a0, a1 = np.asarray(ref.control_points)[[0, -1]]
        b = np.asarray(out.control_points)[[-1, 0] if r.reversed else [0, -1]]
        worst = max(np.linalg.norm(a0 - b[0]), np.linalg.norm(a1 - b[1]))
        assert worst == pytest.approx(r.endpoint_distance, abs=1e-12)
        # reference_end / output_end are those ends, ours matched to the reference's.
        assert np.array_equal(np.asarray(r.reference_end), np.stack([a0, a1]))
        assert np.array_equal(np.asarray(r.output_end), b)
        assert r.constraints_considered == len(r.constraints)
        assert r.constraints_enforced == sum(c.enforced for c in r.constraints)
        # Two-sided distances to the stroke's samples bound each sample's
        # distance to the curve (up to the curve's sampling).
        samples = np.asarray(drawn[r.stroke].points)
        for curve, bound in ((out, r.output_stroke_distance), (ref, r.reference_stroke_distance)):
            pts = curve.sample(512)
            far = max(np.min(np.linalg.norm(pts - p, axis=1)) for p in samples)
            assert far <= bound + 2e-3 * curve.length()


def test_long_calls_release_the_gil(sl, small):
    # Ticks of the main thread counted inside the replay call itself: with the
    # GIL held there would be none, whatever the machine's load (a count over
    # the whole thread's life also counts ticks between calls and, on a loaded
    # machine, too few of them).
    stack = sl.stack("cassie")
    ticks = []
    spans = []
    done = threading.Event()

    def work():
        for _ in range(3):
            start = time.perf_counter()
            sl.replay(small, stack)
            spans.append((start, time.perf_counter()))
        done.set()

    t = threading.Thread(target=work)
    t.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.0005)
    t.join()
    inside = [x for x in ticks if any(a < x < b for a, b in spans)]
    longest = max(b - a for a, b in spans)
    # The main thread kept running Python while the replay ran.
    assert len(inside) >= 1, (len(ticks), longest)
