"""Command-line arguments shared by the trace examples: session names and
`--param NAME=VALUE` pairs, as `sketchlab fidelity` takes them."""
import glob
import os


def parse(argv, default_sessions="structured"):
    """(sessions, params) from argv.

    A value reads as true/false, a number or else a string. With no session
    named: "structured", the Armature/Patch study sessions and the showcase
    sketches of data/recordings; "logged", every session with a raw_data log
    but the Freehand ones; "all", every session of data/recordings."""
    params, sessions = {}, []
    it = iter(argv)
    for arg in it:
        if arg != "--param":
            sessions.append(arg)
            continue
        key, value = next(it).split("=", 1)
        params[key] = {"true": True, "false": False}.get(value, value)
        if isinstance(params[key], str):
            try:
                params[key] = float(value) if "." in value or "e" in value else int(value)
            except ValueError:
                pass
    if not sessions:
        if default_sessions == "all":
            sessions = sorted(os.path.basename(p)[:-6] for p in glob.glob("data/recordings/*.jsonl"))
        elif default_sessions == "logged":
            sessions = sorted(os.path.basename(p)[:-5] for p in glob.glob("data/cassie/raw_data/*.json")
                              if "-0-" not in os.path.basename(p))
        else:
            sessions = sorted(os.path.basename(p)[:-6] for p in glob.glob("data/recordings/0?-[12]-?.jsonl")
                              + glob.glob("data/recordings/[a-z]*.jsonl"))
    return sessions, params
