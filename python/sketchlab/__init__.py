"""sketchlab for Python: the kernel's C++ API (docs/python.md).

Everything here wraps the C++ kernel (sketchlab._sketchlab); this file only
finds the plugins and adds shortcuts over it:

    import sketchlab as sl
    rec = sl.read_recording("data/cassie/....jsonl")
    result = sl.replay(rec, sl.stack("cassie"))
    result.sketch.network.curves          # {id: NetworkCurve}
"""
import json as _json
import os as _os

from ._sketchlab import *  # noqa: F401,F403
from ._sketchlab import (Event, PluginHost, instantiate_stack, load_experiment, load_stack,
                         make_stack, run_experiment, __version__)  # noqa: F401

_host = None


def plugin_search_paths():
    """The directories plugins load from (PluginHost.default_search_paths):
    SKETCHLAB_PLUGIN_PATH's, then the plugins of the build or install tree
    this package belongs to."""
    return [str(d) for d in PluginHost.default_search_paths()]


def host():
    """The plugin host with every plugin of plugin_search_paths(), loaded once."""
    global _host
    if _host is None:
        h = PluginHost()
        h.load_directories(plugin_search_paths())
        _host = h
    return _host


def plugins(kind=None):
    """Loaded plugins, optionally of one kind ("corrector", "surfacer", "input")."""
    return [p for p in host().plugins if kind is None or p.kind.name == kind]


def stack(corrector, params=None, surfacer=None, surfacer_params=None, name=None, time_budget=None):
    """A stack from plugin names and parameters (the checks and errors of a stack file)."""
    return make_stack(host(), corrector, params or {}, surfacer, surfacer_params or {}, name, time_budget)


def stack_from_file(path, overrides=()):
    """A stack from a stack YAML file."""
    return instantiate_stack(load_stack(path, list(overrides)), host())


def corrector(name, params=None):
    """A corrector object, e.g. for teacher_forced()."""
    return host().make_corrector(name, params or {})


def experiment(path, overrides=(), jobs=0, timings=True):
    """Runs an experiment file (as `sketchlab run`); returns the RunSummary."""
    return run_experiment(load_experiment(path, list(overrides)), host(), jobs, timings)


def metrics_rows(summary):
    """One dict per case: recording, stack, ok, error, then every metric."""
    rows = []
    for c in summary.cases:
        row = {"recording": _os.path.basename(str(c.recording)), "stack": c.stack, "ok": c.ok,
               "error": c.error}
        row.update(c.metrics)
        rows.append(row)
    return rows


def _event_to_dict(self):
    """The event as the recording format's JSON object (event_json.hpp)."""
    return _json.loads(self.to_json())


Event.to_dict = _event_to_dict
