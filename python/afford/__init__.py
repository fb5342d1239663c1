"""afford: infer what an articulated hand tool is for by simulating it.

The Python face of the afford C++ engine (docs/python.md). Units are SI
throughout: metres, newtons, seconds, radians.

    import afford
    model = afford.load("sessions/paper-nutcracker.yaml")
    result = model.run()            # functions inferred, and the trace as NumPy arrays
    state = model.state()           # or step it yourself, frame by frame
    frame = state.step((0.1, 0.05, 0.1))

A mistake in a file raises afford.DataError with .file, .line, .column and
.message.
"""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

from . import _afford

__all__ = [
    "DataError", "Model", "State", "Frame", "FrameEvent",
    "load", "compile", "explore", "gap", "check", "effects", "signals", "export_mjcf", "data_dir",
]

DataError = _afford.DataError
Frame = _afford.Frame
FrameEvent = _afford.FrameEvent
State = _afford.State
for _exported in (DataError, Frame, FrameEvent, State):
    _exported.__module__ = __name__  # "afford.DataError" in tracebacks, not "afford._afford.DataError"

PathLike = Union[str, "os.PathLike[str]"]


class Model:
    """A compiled session: a tool, its actee (if any), the hand, the
    function models and the hand's script. Immutable; run it as often as
    you like, or make states from it and step them."""

    def __init__(self, compiled: "_afford.Model") -> None:
        self._compiled = compiled

    @property
    def name(self) -> str:
        """The session's name (`session:`)."""
        return self._compiled.name

    @property
    def description(self) -> str:
        """The session's one-line description."""
        return self._compiled.description

    @property
    def timestep(self) -> float:
        """s, one frame (default 1 ms)."""
        return self._compiled.timestep

    @property
    def duration(self) -> float:
        """s, the script's length: run() steps duration / timestep frames."""
        return self._compiled.duration

    @property
    def functions(self) -> List[str]:
        """The names of the function models, in their file's order."""
        return self._compiled.functions

    @property
    def files(self) -> List[str]:
        """Every file the session read, the session first."""
        return self._compiled.files

    @property
    def warnings(self) -> List[str]:
        """What the hand can never do in this session ('file:line:col: warning: ...')."""
        return self._compiled.warnings

    def run(self) -> Dict[str, Any]:
        """Runs the session's script to its end, as `afford run --json` does.

        Returns a dict:
          "session": the session's name;
          "functions": the inferred functions in order, each
              {"name", "t" (s), "explanation": [{"t" (s), "text", "detail"?}]};
          "frames": the number of frames stepped;
          "trace": the columns of trace.csv (docs/trace-format.md) as NumPy
              arrays of one value per frame: t (s), angle (rad),
              effort_force (N), actee_force (N), effort_pos (m), broken,
              grasped, held (bool), contacts_object_actee (int32),
              actee_load (N). No copy: each array owns the buffer the run
              filled.
        The GIL is released while it runs.
        """
        return self._compiled.run()

    def state(self) -> State:
        """A fresh state of this session (bodies at their start, lever at
        rest, no rule reached) to step frame by frame:

            state = model.state()
            frame = state.step((x, y, z))   # the thumb's target, m, world
            frame = state.step()            # the script's own thumb

        Each step is the next frame (t = k * timestep, s): the hand's pose,
        its other fingers and its joints come from the session's script at
        that time (its last keyframe once it has ended), the thumb's
        fingertip from the sample. Returns an afford.Frame: t (s), angle
        (rad), effort_force (N, the hand's push at the thumb), actee_force
        (N), actee_load (N), finger_forces (N per finger, thumb first: the
        haptic output), grasped, held, broken, and events (this frame's
        afford.FrameEvent list: kind, function, node, text, t).
        state.script_thumb(t) gives the script's thumb target at t (m,
        world); state.functions() what was inferred so far, as run() gives
        it. The same samples give the same frames, bit for bit.
        """
        return _afford.make_state(self._compiled)

    def __repr__(self) -> str:
        return f"<afford.Model {self.name}>"


def _path(p: PathLike) -> str:
    return os.fspath(p)


def data_dir() -> str:
    """The folder of afford's shipped data (rules/, agents/, actees/,
    objects/, sessions/): $AFFORD_DATA_DIR, or the installed
    share/afford (/usr/local/share/afford after the README's set-up)."""
    return _afford.data_dir()


def _shipped(relative: str) -> str:
    return os.path.join(data_dir(), relative)


def load(session_path: PathLike) -> Model:
    """Loads and compiles a session file (sessions/*.yaml). A mistake in it
    or in a file it names raises afford.DataError at its file:line:col."""
    return Model(_afford.load(_path(session_path)))


def compile(object: PathLike, actee: Union[None, PathLike, Mapping[str, Any]] = None, *,
            script: Sequence[Mapping[str, Any]],
            agent: Optional[PathLike] = None, rules: Optional[PathLike] = None,
            grasps: Optional[PathLike] = None, name: str = "python",
            timestep: Optional[str] = None) -> Model:
    """Compiles a session from its parts, as a session file would name them.

    object: the tool's object file.
    actee: an actee file (then `at` is needed: pass a mapping instead), or a
        mapping as a session's `actee:` ({"file": path, "at": "60 mm"} or
        {"file": path, "position": ["0 mm", "0 mm", "0 mm"]}); None: no actee.
    script: the hand's keyframes, as a session's `script:` list (values
        with their units as text: {"t": "0.4 s", "grip": {"thumb": "160 mm",
        "index": "160 mm", "squeeze": "0 mm"}, "posture": "medium_wrap"}).
    agent, rules, grasps: the hand, the function models and the grasp
        taxonomy; default the shipped agents/hand.yaml, rules/functions.yaml
        and rules/grasps.yaml.
    timestep: optional, with its unit ("1 ms").

    A mistake raises afford.DataError; one in the parts given here names
    the generated document "<afford.compile NAME>" with its line and column.
    """
    doc: Dict[str, Any] = {"session": name, "description": "compiled from Python"}
    doc["object"] = os.path.abspath(_path(object))
    if actee is not None:
        if isinstance(actee, Mapping):
            given = dict(actee)
            if "file" in given:
                given["file"] = os.path.abspath(_path(given["file"]))
            doc["actee"] = given
        else:
            raise TypeError("actee: pass a mapping with its place, e.g. {'file': path, 'at': '60 mm'}")
    doc["agent"] = os.path.abspath(_path(agent)) if agent is not None else _shipped("agents/hand.yaml")
    doc["rules"] = os.path.abspath(_path(rules)) if rules is not None else _shipped("rules/functions.yaml")
    doc["grasps"] = os.path.abspath(_path(grasps)) if grasps is not None else _shipped("rules/grasps.yaml")
    if timestep is not None:
        doc["timestep"] = timestep
    doc["script"] = list(script)
    # JSON is YAML: the engine reads it as any session file, line by line.
    text = json.dumps(doc, indent=2)
    return Model(_afford.compile_text(text, f"<afford.compile {name}>"))


def explore(object: PathLike, actees: Optional[Sequence[PathLike]] = None, *,
            agent: Optional[PathLike] = None, rules: Optional[PathLike] = None,
            taxonomy: Optional[PathLike] = None, placements: int = 3, thumbs: int = 3,
            efforts: int = 9, max_effort: float = 0.0, fixed_efforts: bool = False,
            grasps: Sequence[str] = (), tolerance: float = 0.5,
            threads: int = 0) -> Dict[str, Any]:
    """One tool on every actee, placement, thumb, grasp type and effort, as
    `afford explore` (explore/README.md).

    actees: actee files or folders of them (default: the shipped actees).
    placements, thumbs, efforts: points per axis; max_effort: N, the common
    axis's top (0: the hand's limit); fixed_efforts: one effort axis for all
    actees instead of each scaled to where it turns; grasps: grasp type
    names (default: every type); tolerance: N, of the thresholds; threads:
    worker threads (0: every core).

    Returns the points as a dict of NumPy columns, one row per point, the
    columns of points.csv: actee, grasp, outcome (str); placement_m,
    thumb_m (m); effort_N, applied_effort_N (N); applied_s and one
    <function>_s per function model (s, NaN: never); peak_effort_N,
    peak_actee_force_N (N); broke_s (s, NaN: never). pandas.DataFrame takes
    it as it is. Runs on every core with the GIL released (other Python
    threads go on); the same bits whatever the number of threads.
    A bad grid value raises ValueError, a bad file afford.DataError.
    """
    if threads < 0:
        raise ValueError(f"threads: expected 0 (every core) or more, found {threads}")
    files: List[str] = []
    for given in (actees if actees is not None else [_shipped("actees")]):
        given = _path(given)
        if os.path.isdir(given):
            found = sorted(os.path.join(given, f) for f in os.listdir(given) if f.endswith(".yaml"))
            if not found:
                raise ValueError(f"actees: no .yaml file in the folder {given}")
            files.extend(found)
        else:
            files.append(given)  # the loader says what is wrong with it
    return _afford.explore(
        os.path.abspath(_path(object)), files,
        _path(agent) if agent is not None else _shipped("agents/hand.yaml"),
        _path(rules) if rules is not None else _shipped("rules/functions.yaml"),
        _path(taxonomy) if taxonomy is not None else _shipped("rules/grasps.yaml"),
        placements, thumbs, efforts, float(max_effort), fixed_efforts, list(grasps), float(tolerance), threads)


def gap(measurement_path: PathLike, effects: Sequence[str] = ()) -> Dict[str, Any]:
    """Where a measured tool differs from its model, which effect explains
    it, and how far the gap shrinks held out: the report of `afford gap
    --json` as a dict (gap/README.md; units in its keys). effects: the
    effect names to try (default: every one that applies); an unknown name
    raises ValueError with "did you mean"."""
    return json.loads(_afford.gap_json(_path(measurement_path), list(effects)))


def check(path: PathLike) -> Dict[str, Any]:
    """Validates any file afford reads (object, actee, agent, functions,
    grasps, guides, session, device, rule test, measurement), as `afford
    check`. Returns {"what": "<kind> <name>", "warnings": [{"file", "line",
    "column", "message"}]}; raises afford.DataError at the first mistake."""
    return _afford.check(_path(path))


def effects() -> List[Dict[str, Any]]:
    """The optional effects a file can switch on (`afford describe
    --effects`): each {"name", "home" (the kind of file), "doc", "params":
    [{"key", "unit" (SI), "min", "min_included", "max", "keeps_sign", "range", "doc"}]}."""
    return _afford.effects()


def signals() -> List[Dict[str, Any]]:
    """The signals function models are written over (`afford rules
    --list`): each {"signature", "type" (with its unit), "doc"}."""
    return _afford.signals()


def export_mjcf(session: Union[PathLike, Model]) -> str:
    """The session as a MuJoCo 2.2.2 scene (MJCF XML text), as `afford
    export --mjcf` writes it; a session file's path or a Model. A session
    with several actees raises RuntimeError."""
    compiled = session._compiled if isinstance(session, Model) else _afford.load(_path(session))
    return _afford.export_mjcf(compiled)
